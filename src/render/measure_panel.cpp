#include "render/measure_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace noneuclid::render {

namespace {

// A line by a printf format (checked at each call: the attribute).
[[gnu::format(printf, 2, 3)]] void line(MeasurePanel& p, const char* format, ...) {
    if (p.lines >= MeasurePanel::kLines) return;
    std::va_list args;
    va_start(args, format);
    std::vsnprintf(p.text[p.lines++], MeasurePanel::kWidth, format, args);
    va_end(args);
}

// A sentence in lines of at most `width` characters, broken at spaces.
void sentence(MeasurePanel& p, const char* s, std::size_t width) {
    while (*s && p.lines < MeasurePanel::kLines) {
        std::size_t n = std::min(std::strlen(s), width);
        if (s[n] != '\0')
            for (std::size_t k = n; k > 0; --k)
                if (s[k] == ' ') {
                    n = k;
                    break;
                }
        std::snprintf(p.text[p.lines++], MeasurePanel::kWidth, "%.*s", static_cast<int>(n), s);
        s += n;
        while (*s == ' ') ++s;
    }
}

// Characters on the screen: UTF-8 bytes that do not continue a character ("°" is one).
int columns(const char* s) {
    int n = 0;
    for (; *s; ++s) n += (*s & 0xC0) != 0x80;
    return n;
}

// A reading: its label, its value right-aligned to end at column kValueEnd (one space after the
// label at least), and its unit: "°" against the number, as angles are written, a length's or an
// area's after a space; none for a ratio. The value has `decimals` places, fewer where it would
// be wider than five characters (six with its sign), so that a line keeps within the panel.
constexpr int kValueEnd = 10;
void reading(MeasurePanel& p, const char* label, double v, int decimals, const char* unit) {
    char value[24];
    for (;; --decimals) {
        std::snprintf(value, sizeof value, "%.*f", decimals, v);
        if (decimals == 0 || static_cast<int>(std::strlen(value)) <= 5 + (value[0] == '-')) break;
    }
    // A value that rounds to zero has no sign ("-0.00" is a rounding error's, not a reading).
    if (value[0] == '-' && std::strspn(value, "-0.") == std::strlen(value))
        std::memmove(value, value + 1, std::strlen(value));
    const int pad = std::max(1, kValueEnd - columns(label) - static_cast<int>(std::strlen(value)));
    const char* space = *unit && std::strcmp(unit, "°") != 0 ? " " : "";
    line(p, "%s%*s%s%s%s", label, pad, "", value, space, unit);
}

}  // namespace

MeasurePanel measure_panel(const world::GaugeReading& r, lang::Language language) {
    using lang::Text;
    const auto t = [language](Text name) { return lang::text(name, language); };
    constexpr Text kNames[] = {Text::instrument_triangle, Text::instrument_circle, Text::instrument_parallels,
                               Text::instrument_polygon};
    MeasurePanel p;
    line(p, "%s", t(kNames[static_cast<int>(r.kind)]));
    if (r.waiting) {
        line(p, t(Text::mark_of), r.marks + 1);
        line(p, t(Text::of_needed), r.needed);
        return p;
    }
    if (r.error != geo::MeasureError::none) {
        sentence(p, geo::measure_error_sentence(r.error), kPanelColumns);
        return p;
    }
    const char* const deg = "°";
    const char* const u = t(Text::unit_length);
    const char* const u2 = t(Text::unit_area);
    switch (r.kind) {
        case geo::Instrument::triangle:
            for (int i = 0; i < 3; ++i) {
                const char name[2] = {static_cast<char>('A' + i), 0};
                reading(p, name, r.triangle.angle_deg[i], 1, deg);
            }
            reading(p, t(Text::angle_sum), r.triangle.sum_deg, 1, deg);
            reading(p, "exc", r.triangle.excess_deg, 1, deg);
            reading(p, "area", r.triangle.area, 3, u2);
            reading(p, "K*A", r.triangle.k_area_deg, 1, deg);
            break;
        case geo::Instrument::circle:
            reading(p, "r", r.radius, 3, u);
            reading(p, "C", r.circle.circumference, 3, u);
            reading(p, "C0", r.circle.flat_circumference, 3, u);
            reading(p, "C/C0", r.circle.circumference_ratio, 3, "");
            reading(p, "A", r.circle.area, 3, u2);
            reading(p, "A0", r.circle.flat_area, 3, u2);
            reading(p, "A/A0", r.circle.area_ratio, 3, "");
            break;
        case geo::Instrument::parallels:
            reading(p, "d", r.distance, 3, u);
            reading(p, "s", r.length, 3, u);
            reading(p, "d(s)", r.parallels.distance, 3, u);  // (apart after s)
            reading(p, "ratio", r.parallels.ratio, 3, "");
            if (r.parallels.meet) reading(p, "meet", r.parallels.meet_at, 3, u);
            break;
        case geo::Instrument::polygon:
            line(p, "%d x {%d}", r.around, r.sides);
            reading(p, "a", r.side, 3, u);
            reading(p, "ang", r.polygon.angle_deg, 1, deg);
            reading(p, r.polygon.gap_deg >= 0 ? "gap" : "over", std::fabs(r.polygon.gap_deg), 1, deg);
            line(p, "%s", t(Text::closes_at));
            reading(p, "K", r.polygon.closing_K, 3, "");
            break;
    }
    return p;
}

void draw_measure_panel(const Canvas& c, const Font& font, const MeasurePanel& p, int side, Rgb color, Rgb dim) {
    const int disc = std::min(c.width(), c.height());
    const int room = (c.width() - disc) / 2;
    if (room < 8 * font.width) return;  // no room beside the disc (a square picture): the dump has the numbers
    const int scale = room >= kPanelColumns * 2 * font.width && c.height() >= 10 * 2 * font.height ? 2 : 1;
    const int line_height = font.height * scale + scale * 2;
    const int width = kPanelColumns * font.width * scale;
    const int x = side == 0 ? c.width() - width - std::max(0, (room - width) / 2) : std::max(0, (room - width) / 2);
    int y = (c.height() - p.lines * line_height) / 2;
    for (int i = 0; i < p.lines; ++i, y += line_height) draw_text(c, font, x, y, p.text[i], i == 0 ? dim : color, scale);
}

}  // namespace noneuclid::render
