// The strict TOML reading shared by scene files and board files (toml++): every key must be
// known, every value has a type and a range, and every error carries its place in the file.
// Internal to src/world's .cpp files (they link toml++ privately).
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>
#include <toml++/toml.h>


#include "world/scene.hpp"  // Rgb
#include "world/scene_file.hpp"  // SceneError

namespace noneuclid::world::tomlr {

// Thrown inside the parser, caught at the top, turned into a SceneError.
struct Bad {
    toml::source_region where;
    std::string message;
};

inline const char* type_name(const toml::node& n) {
    switch (n.type()) {
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a number";
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::array: return "an array";
        case toml::node_type::table: return "a table";
        case toml::node_type::date: return "a date";
        case toml::node_type::time: return "a time";
        case toml::node_type::date_time: return "a date-time";
        default: return "nothing";
    }
}

inline std::string quote(std::string_view s) {
    std::string q;  // (built with append: GCC 12 warns falsely on "'" + std::string(s))
    q.reserve(s.size() + 2);
    q.append(1, '\'').append(s).append(1, '\'');
    return q;
}

class Reader {
public:
    Reader(const toml::table& t, std::string context) : t_(t), context_(std::move(context)) {}

    // Every key must be one we know: a typo is an error, not a silently ignored line.
    void only(std::initializer_list<const char*> known) const {
        for (auto&& [key, node] : t_) {
            bool ok = false;
            for (const char* k : known) ok = ok || key.str() == k;
            if (!ok) {
                std::string list;
                for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
                throw Bad{key.source(), context_ + "unknown key " + quote(key.str()) + " (expected one of: " + list + ")"};
            }
        }
    }

    double number(const char* key, double fallback, double lo, double hi, const char* what) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        return as_number(*n, key, lo, hi, what);
    }
    double as_number(const toml::node& n, const std::string& key, double lo, double hi, const char* what) const {
        double v;
        if (auto f = n.as_floating_point())
            v = f->get();
        else if (auto i = n.as_integer())
            v = static_cast<double>(i->get());
        else
            throw Bad{n.source(), context_ + "expected a number for " + quote(key) + " (" + what + "), found " + type_name(n)};
        if (!std::isfinite(v) || v < lo || v > hi) {
            std::ostringstream m;
            m << context_ << quote(key) << " must be from " << lo << " to " << hi << " (" << what << "), found " << v;
            throw Bad{n.source(), m.str()};
        }
        return v;
    }
    bool boolean(const char* key, bool fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        if (auto b = n->as_boolean()) return b->get();
        throw Bad{n->source(), context_ + "expected true or false for " + quote(key) + ", found " + type_name(*n)};
    }
    std::string string(const char* key, const std::string& fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        if (auto s = n->as_string()) return s->get();
        throw Bad{n->source(), context_ + "expected a string for " + quote(key) + ", found " + type_name(*n)};
    }
    long integer(const char* key, long fallback, long lo, long hi, const char* what) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        auto i = n->as_integer();
        if (!i) throw Bad{n->source(), context_ + "expected a whole number for " + quote(key) + " (" + what + "), found " + type_name(*n)};
        if (i->get() < lo || i->get() > hi) {
            std::ostringstream m;
            m << context_ << quote(key) << " must be from " << lo << " to " << hi << " (" << what << "), found " << i->get();
            throw Bad{n->source(), m.str()};
        }
        return static_cast<long>(i->get());
    }
    // [a, b]: two numbers.
    bool pair(const char* key, double& a, double& b, double alo, double ahi, const char* what) const {
        const toml::node* n = t_.get(key);
        if (!n) return false;
        const toml::array* arr = n->as_array();
        if (!arr || arr->size() != 2)
            throw Bad{n->source(), context_ + "expected " + quote(key) + " = [" + what + "], found " +
                                       (arr ? "an array of " + std::to_string(arr->size()) : std::string(type_name(*n)))};
        a = as_number(*arr->get(0), key, alo, ahi, what);
        b = as_number(*arr->get(1), key, -1e6, 1e6, what);
        return true;
    }
    Rgb color(const char* key, Rgb fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        auto s = n->as_string();
        const std::string v = s ? s->get() : "";
        auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
        if (!s || v.size() != 7 || v[0] != '#' || !std::all_of(v.begin() + 1, v.end(), hex))
            throw Bad{n->source(), context_ + "expected a colour \"#rrggbb\" for " + quote(key) + ", found " +
                                       (s ? "\"" + v + "\"" : std::string(type_name(*n)))};
        const unsigned long x = std::stoul(v.substr(1), nullptr, 16);
        return {static_cast<uint8_t>(x >> 16), static_cast<uint8_t>(x >> 8), static_cast<uint8_t>(x)};
    }
    const toml::table& table() const { return t_; }

private:
    const toml::table& t_;
    std::string context_;
};

// [[body]], [[grid]], [[button]]: arrays of tables (null when the key is absent).
inline const toml::array* tables(const toml::table& root, const char* key) {
    const toml::node* n = root.get(key);
    if (!n) return nullptr;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables())
        throw Bad{n->source(), std::string("expected [[") + key + "]] tables, found " + type_name(*n)};
    return a;
}

// Parses `text` as TOML and hands the root table to `read`; a syntax error or a Bad thrown by
// `read` becomes `error` (file:line:column: message). Returns true on success.
template <class Read>
bool parse_toml(const std::string& text, const std::string& name, SceneError& error, Read&& read) {
    try {
        const toml::table root = toml::parse(text, name);
        read(root);
        return true;
    } catch (const toml::parse_error& e) {
        error = {name, static_cast<long>(e.source().begin.line), static_cast<long>(e.source().begin.column),
                 "not valid TOML: " + std::string(e.description())};
    } catch (const Bad& b) {
        error = {name, static_cast<long>(b.where.begin.line), static_cast<long>(b.where.begin.column), b.message};
    }
    return false;
}

}  // namespace noneuclid::world::tomlr
