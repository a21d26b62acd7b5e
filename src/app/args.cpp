#include "app/args.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

#include "world/quote.hpp"

namespace noneuclid::app {

void usage_error(const std::string& message) { throw UsageError{message}; }

Args::Args(std::vector<std::string> words) {
    for (std::string& w : words) {
        const std::size_t eq = w.find('=');
        if (w.size() > 2 && w.compare(0, 2, "--") == 0 && eq != std::string::npos && eq > 2) {
            words_.push_back(w.substr(0, eq)), attached_.push_back(false);
            words_.push_back(w.substr(eq + 1)), attached_.push_back(true);
        } else {
            words_.push_back(std::move(w)), attached_.push_back(false);
        }
    }
}

const std::string& Args::value(const std::string& opt) {
    if (!more()) usage_error(opt + " needs a value; " + help_hint() + ".");
    const std::string& v = next();
    if (v.empty()) usage_error(opt + " needs a value, not an empty word; " + help_hint() + ".");
    return v;
}

double Args::parse_number(const std::string& opt, const std::string& text, double lo, double hi) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(v >= lo && v <= hi)) {
        char range[64];
        std::snprintf(range, sizeof range, "%g to %g", lo, hi);
        usage_error(opt + " needs a number from " + range + ", not '" + text + "'.");
    }
    return v;
}

long long Args::parse_count(const std::string& opt, const std::string& text, long long lo, long long hi) {
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || v < lo || v > hi)
        usage_error(opt + " needs a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", not '" +
                    text + "'.");
    return v;
}

void parse_size(const std::string& opt, const std::string& text, int& width, int& height) {
    // Digits only, each side at most five of them: no sign, no space, nothing that overflows.
    const std::size_t x = text.find('x');
    auto side = [&](std::size_t from, std::size_t to) -> long {
        if (to <= from || to - from > 5) return -1;
        long v = 0;
        for (std::size_t i = from; i < to; ++i) {
            if (text[i] < '0' || text[i] > '9') return -1;
            v = v * 10 + (text[i] - '0');
        }
        return v;
    };
    const long w = x == std::string::npos ? -1 : side(0, x), h = x == std::string::npos ? -1 : side(x + 1, text.size());
    if (w < 16 || h < 16 || w > 16384 || h > 16384)
        usage_error(opt + " needs WIDTHxHEIGHT in pixels, 16 to 16384 each (e.g. 800x480), not '" + text + "'.");
    width = static_cast<int>(w), height = static_cast<int>(h);
}

geo::Projection parse_projection(const std::string& opt, const std::string& text) {
    geo::Projection p{};
    if (!geo::parse_projection_name(text, p))
        usage_error(opt + " must be " + world::or_list(geo::projection_names()) + ", not '" + text + "'.");
    return p;
}

render::PixelFormat parse_format(const std::string& opt, const std::string& text) {
    std::vector<std::string> names;
    for (const render::PixelFormat& f : render::kNamedFormats) {
        if (text == f.name) return f;
        names.emplace_back(f.name);
    }
    usage_error(opt + " must be " + world::or_list(names) + ", not '" + text + "'.");
}

bool parse_on_off(const std::string& opt, const std::string& text) {
    if (text == "on") return true;
    if (text == "off") return false;
    usage_error(opt + " must be on or off, not '" + text + "'.");
}

}  // namespace noneuclid::app
