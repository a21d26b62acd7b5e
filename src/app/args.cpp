#include "app/args.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

namespace noneuclid::app {

void usage_error(const std::string& message) { throw UsageError{message}; }

const std::string& Args::value(const std::string& opt) {
    if (!more()) usage_error(opt + " needs a value; see 'noneuclid --help'.");
    return next();
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
    int w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16 || w > 16384 || h > 16384)
        usage_error(opt + " needs WIDTHxHEIGHT in pixels, 16 to 16384 each (e.g. 800x480), not '" + text + "'.");
    width = w, height = h;
}

geo::Projection parse_projection(const std::string& opt, const std::string& text) {
    for (geo::Projection p : geo::kProjections)
        if (text == geo::projection_name(p)) return p;
    usage_error(opt + " must be equidistant, stereographic, gnomonic, orthographic or lambert, not '" + text + "'.");
}

render::PixelFormat parse_format(const std::string& opt, const std::string& text) {
    for (render::PixelFormat f :
         {render::PixelFormat::xrgb8888(), render::PixelFormat::rgb565(), render::PixelFormat::rgb888()})
        if (text == f.name) return f;
    usage_error(opt + " must be xrgb8888, rgb565 or rgb888, not '" + text + "'.");
}

bool parse_on_off(const std::string& opt, const std::string& text) {
    if (text == "on") return true;
    if (text == "off") return false;
    usage_error(opt + " must be on or off, not '" + text + "'.");
}

}  // namespace noneuclid::app
