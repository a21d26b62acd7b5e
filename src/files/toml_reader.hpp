// The strict TOML reading shared by scene files and board files (toml++): every key must be
// known, every value has a type and a range, and every error carries its place in the file.
// Internal to src/world's .cpp files (they link toml++ privately).
//
// toml++ 3.3.0 (Debian 12) and 3.4.0 (the newest in any Debian suite: trixie, sid) abort in
// their own assertions, or reach __builtin_unreachable (undefined behaviour; with assertions
// off, as in a release build, they become assumptions), on ordinary text: any non-ASCII
// character outside quotes (`κ = 0.5`, `x = Ж`, `curvature = 0.5 ¡`: its whitespace table
// has holes, upstream issue 295, fixed after 3.4.0), a lone carriage return after `[[` or `[`
// (an assertion in parse_key), a non-ASCII character after a line-ending backslash (issue
// 190). So toml_guard() reads the text first and refuses, with its place, what TOML does not
// allow anyway and what reaches those paths; toml++ never sees such a text.
// (tests/world/test_hostile.cpp has inputs for each rule; tests/fuzz/regressions/ keeps those
// the fuzzers found, replayed by the normal suite.) Messages quote
// file content through world/quote.hpp, toml++'s own descriptions included.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>
#include <toml++/toml.h>

#include "world/quote.hpp"
#include "world/scene.hpp"  // Rgb
#include "files/scene_file.hpp"  // SceneError

namespace noneuclid::files::tomlr {

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

// Checks `text` before toml++ parses it (see the top of this file). Refuses, with the place
// (line and column, 1-based, columns in characters as toml++ counts them) and one sentence
// beginning "not valid TOML: ":
//  - bytes that are not UTF-8; control characters but tab and line ends (a carriage return
//    only before a line feed), anywhere;
//  - a non-ASCII character outside a quoted string or a comment (a quote counts as the start of
//    a string only where a key or a value may begin: after '=', '[', '{', ',', '.' or at the
//    start of a line; elsewhere toml++ reads it as part of a bad token);
//  - a table header whose name does not begin with a key's character or a quote (`[*]`);
//  - a ']' or '}' that does not match the innermost open array or inline table;
//  - a non-ASCII character right after a backslash and whitespace in a basic string (a
//    line-ending backslash).
// TOML 1.0 allows none of these but the last, whose character can be written as an escape
// instead. Returns true when the text may be parsed.
bool toml_guard(std::string_view text, long& line, long& column, std::string& message);

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
                throw Bad{key.source(), context_ + "unknown key " + world::quote(key.str()) + " (expected one of: " + list + ")"};
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
            throw Bad{n.source(), context_ + "expected a number for " + world::quote(key) + " (" + what + "), found " + type_name(n)};
        if (!std::isfinite(v) || v < lo || v > hi) {
            std::ostringstream m;
            m << context_ << world::quote(key) << " must be from " << lo << " to " << hi << " (" << what << "), found " << v;
            throw Bad{n.source(), m.str()};
        }
        return v;
    }
    bool boolean(const char* key, bool fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        if (auto b = n->as_boolean()) return b->get();
        throw Bad{n->source(), context_ + "expected true or false for " + world::quote(key) + ", found " + type_name(*n)};
    }
    std::string string(const char* key, const std::string& fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        if (auto s = n->as_string()) return s->get();
        throw Bad{n->source(), context_ + "expected a string for " + world::quote(key) + ", found " + type_name(*n)};
    }
    // A string that is shown or used as it is (a device path, a chip label, a scene's path): no
    // control characters in it (world::is_plain).
    std::string plain_string(const char* key, const std::string& fallback) const {
        std::string v = string(key, fallback);
        if (!world::is_plain(v)) throw Bad{t_.get(key)->source(), not_plain(key, v)};
        return v;
    }
    std::string not_plain(const std::string& key, const std::string& v) const {
        return context_ + "expected " + world::quote(key) + " without control characters, found " + world::quote(v);
    }
    long integer(const char* key, long fallback, long lo, long hi, const char* what) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        auto i = n->as_integer();
        if (!i) throw Bad{n->source(), context_ + "expected a whole number for " + world::quote(key) + " (" + what + "), found " + type_name(*n)};
        if (i->get() < lo || i->get() > hi) {
            std::ostringstream m;
            m << context_ << world::quote(key) << " must be from " << lo << " to " << hi << " (" << what << "), found " << i->get();
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
            throw Bad{n->source(), context_ + "expected " + world::quote(key) + " = [" + what + "], found " +
                                       (arr ? "an array of " + std::to_string(arr->size()) : std::string(type_name(*n)))};
        a = as_number(*arr->get(0), key, alo, ahi, what);
        b = as_number(*arr->get(1), key, -1e6, 1e6, what);
        return true;
    }
    world::Rgb color(const char* key, world::Rgb fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        auto s = n->as_string();
        const std::string v = s ? s->get() : "";
        auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
        if (!s || v.size() != 7 || v[0] != '#' || !std::all_of(v.begin() + 1, v.end(), hex))
            throw Bad{n->source(), context_ + "expected a colour \"#rrggbb\" for " + world::quote(key) + ", found " +
                                       (s ? "\"" + world::printable(v) + "\"" : std::string(type_name(*n)))};
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
    if (!toml_guard(text, error.line, error.column, error.message)) {
        error.file = name;
        return false;
    }
    try {
        const toml::table root = toml::parse(text, std::string(name));
        read(root);
        return true;
    } catch (const toml::parse_error& e) {
        // Its description may name a key or show a character of the file: quoted like ours.
        error = {name, static_cast<long>(e.source().begin.line), static_cast<long>(e.source().begin.column),
                 "not valid TOML: " + world::printable(e.description(), world::kSentenceLimit, false)};
    } catch (const Bad& b) {
        error = {name, static_cast<long>(b.where.begin.line), static_cast<long>(b.where.begin.column), b.message};
    }
    return false;
}

}  // namespace noneuclid::files::tomlr
