#include "render/measure_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>

#include "render/layout.hpp"

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

// A value with `decimals` places, fewer where it would be wider than five characters (six with
// its sign), so that a line keeps within the panel; a value that rounds to zero has no sign
// ("-0.00" is a rounding error's, not a reading).
void add(PanelReadings& out, const char* label, double v, int decimals, const char* unit) {
    if (out.count >= PanelReadings::kMax) return;
    PanelReading& r = out.row[out.count++];
    for (;; --decimals) {
        std::snprintf(r.value, sizeof r.value, "%.*f", decimals, v);
        if (decimals == 0 || static_cast<int>(std::strlen(r.value)) <= 5 + (r.value[0] == '-')) break;
    }
    if (r.value[0] == '-' && std::strspn(r.value, "-0.") == std::strlen(r.value))
        std::memmove(r.value, r.value + 1, std::strlen(r.value));
    std::snprintf(r.label, sizeof r.label, "%s", label);
    std::snprintf(r.unit, sizeof r.unit, "%s", unit);
}

// A reading's line: its label, its value right-aligned to end at column kValueEnd (one space
// after the label at least), and its unit: "°" against the number, as angles are written, a
// length's or an area's after a space; none for a ratio.
constexpr int kValueEnd = 10;
void reading(MeasurePanel& p, const PanelReading& r) {
    const int pad = std::max(1, kValueEnd - columns(r.label) - static_cast<int>(std::strlen(r.value)));
    const char* space = *r.unit && std::strcmp(r.unit, "°") != 0 ? " " : "";
    line(p, "%s%*s%s%s%s", r.label, pad, "", r.value, space, r.unit);
}

}  // namespace

PanelReadings panel_readings(const world::GaugeReading& r, lang::Language language) {
    using lang::Text;
    const auto t = [language](Text name) { return lang::text(name, language); };
    PanelReadings out;
    if (r.waiting || r.error != geo::MeasureError::none) return out;
    const char* const deg = "°";
    const char* const u = t(Text::unit_length);
    const char* const u2 = t(Text::unit_area);
    switch (r.kind) {
        case geo::Instrument::triangle:
            for (int i = 0; i < 3; ++i) {
                const char name[2] = {static_cast<char>('A' + i), 0};
                add(out, name, r.triangle.angle_deg[i], 1, deg);
            }
            add(out, t(Text::angle_sum), r.triangle.sum_deg, 1, deg);
            add(out, t(Text::label_excess), r.triangle.excess_deg, 1, deg);
            add(out, t(Text::label_area), r.triangle.area, 3, u2);
            add(out, "K*A", r.triangle.k_area_deg, 1, deg);
            break;
        case geo::Instrument::circle:
            add(out, "r", r.radius, 3, u);
            add(out, "C", r.circle.circumference, 3, u);
            add(out, "C0", r.circle.flat_circumference, 3, u);
            add(out, "C/C0", r.circle.circumference_ratio, 3, "");
            add(out, "A", r.circle.area, 3, u2);
            add(out, "A0", r.circle.flat_area, 3, u2);
            add(out, "A/A0", r.circle.area_ratio, 3, "");
            break;
        case geo::Instrument::parallels:
            add(out, "d", r.distance, 3, u);
            add(out, "s", r.length, 3, u);
            add(out, "d(s)", r.parallels.distance, 3, u);  // (apart after s)
            add(out, t(Text::label_ratio), r.parallels.ratio, 3, "");
            if (r.parallels.meet) add(out, t(Text::label_meet), r.parallels.meet_at, 3, u);
            break;
        case geo::Instrument::polygon:
            add(out, "a", r.side, 3, u);
            add(out, t(Text::label_angle), r.polygon.angle_deg, 1, deg);
            add(out, t(r.polygon.gap_deg >= 0 ? Text::label_gap : Text::label_over), std::fabs(r.polygon.gap_deg), 1, deg);
            add(out, "K", r.polygon.closing_K, 3, "");  // (the K at which it closes)
            break;
    }
    return out;
}

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
    const PanelReadings rows = panel_readings(r, language);
    const bool polygon = r.kind == geo::Instrument::polygon;
    if (polygon) line(p, "%d x {%d}", r.around, r.sides);
    for (int i = 0; i < rows.count; ++i) {
        if (polygon && i + 1 == rows.count) line(p, "%s", t(Text::closes_at));  // (before its K)
        reading(p, rows.row[i]);
    }
    return p;
}

void draw_measure_panel(const Canvas& c, const Font& font, const MeasurePanel& p, const Box& at, int scale, Rgb color,
                        Rgb dim) {
    if (at.empty()) return;  // no room beside the disc (render/layout.hpp)
    const int line_height = font.height * scale + scale * 2;
    int y = at.y + (at.h - p.lines * line_height) / 2;
    for (int i = 0; i < p.lines; ++i, y += line_height) draw_text(c, font, at.x, y, p.text[i], i == 0 ? dim : color, scale);
}

}  // namespace noneuclid::render
