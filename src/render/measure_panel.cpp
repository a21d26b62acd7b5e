#include "render/measure_panel.hpp"

#include <algorithm>
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
        sentence(p, geo::measure_error_sentence(r.error), 11);
        return p;
    }
    switch (r.kind) {
        case geo::Instrument::triangle:
            for (int i = 0; i < 3; ++i) line(p, "%c    %6.2f", 'A' + i, r.triangle.angle_deg[i]);
            line(p, "%-4s %6.2f", t(Text::angle_sum), r.triangle.sum_deg);
            line(p, "exc  %6.2f", r.triangle.excess_deg);
            line(p, "area %6.3f", r.triangle.area);
            line(p, "K*A  %6.2f", r.triangle.k_area_deg);
            break;
        case geo::Instrument::circle:
            line(p, "r    %6.3f", r.radius);
            line(p, "C    %6.3f", r.circle.circumference);
            line(p, "C0   %6.3f", r.circle.flat_circumference);
            line(p, "C/C0 %6.3f", r.circle.circumference_ratio);
            line(p, "A    %6.3f", r.circle.area);
            line(p, "A0   %6.3f", r.circle.flat_area);
            line(p, "A/A0 %6.3f", r.circle.area_ratio);
            break;
        case geo::Instrument::parallels:
            line(p, "d     %5.3f", r.distance);
            line(p, "s     %5.3f", r.length);
            line(p, "apart %5.3f", r.parallels.distance);
            line(p, "ratio %5.3f", r.parallels.ratio);
            if (r.parallels.meet) line(p, "meet  %5.3f", r.parallels.meet_at);
            break;
        case geo::Instrument::polygon:
            line(p, "%d x {%d}", r.around, r.sides);
            line(p, "a    %6.3f", r.side);
            line(p, "ang  %6.2f", r.polygon.angle_deg);
            line(p, "%s %6.2f", r.polygon.gap_deg >= 0 ? "gap " : "over", r.polygon.gap_deg >= 0 ? r.polygon.gap_deg : -r.polygon.gap_deg);
            line(p, "%s", t(Text::closes_at));
            line(p, "K   %+7.3f", r.polygon.closing_K);
            break;
    }
    return p;
}

void draw_measure_panel(const Canvas& c, const Font& font, const MeasurePanel& p, int side, Rgb color, Rgb dim) {
    const int disc = std::min(c.width(), c.height());
    const int room = (c.width() - disc) / 2;
    if (room < 8 * font.width) return;  // no room beside the disc (a square picture): the dump has the numbers
    const int scale = room >= 11 * 2 * font.width && c.height() >= 10 * 2 * font.height ? 2 : 1;
    const int line_height = font.height * scale + scale * 2;
    const int width = 11 * font.width * scale;
    const int x = side == 0 ? c.width() - width - std::max(0, (room - width) / 2) : std::max(0, (room - width) / 2);
    int y = (c.height() - p.lines * line_height) / 2;
    for (int i = 0; i < p.lines; ++i, y += line_height) draw_text(c, font, x, y, p.text[i], i == 0 ? dim : color, scale);
}

}  // namespace noneuclid::render
