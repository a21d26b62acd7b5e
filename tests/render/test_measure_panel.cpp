// The instruments' panel (render/measure_panel.hpp): each reading's line carries its unit (° for
// an angle, the language's unit of length or area, none for a ratio), its number is the
// reading's to the places the line shows (half a unit in the last place), every line fits the
// panel's 13 columns in every language, the built-in font draws every character of it (° and ²
// are not '?'), and drawn beside the kiosk's 800x480 disc no pixel of it falls on the disc.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "render/layout.hpp"
#include "render/measure_panel.hpp"

namespace noneuclid {
namespace {

using render::MeasurePanel;

// The code points of a UTF-8 line.
std::u32string decode(const char* s) {
    std::u32string out;
    for (const unsigned char* p = reinterpret_cast<const unsigned char*>(s); *p;) {
        char32_t c = *p++;
        if (c >= 0xC0) {
            const int more = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : 1;
            c &= 0x3F >> more;
            for (int i = 0; i < more && *p; ++i) c = (c << 6) | (*p++ & 0x3F);
        }
        out += c;
    }
    return out;
}

// The line of the panel that starts with `label` and a space.
std::string line_of(const MeasurePanel& p, const std::string& label) {
    for (int i = 0; i < p.lines; ++i)
        if (std::strncmp(p.text[i], (label + " ").c_str(), label.size() + 1) == 0) return p.text[i];
    ADD_FAILURE() << "no line " << label;
    return "";
}

// Checks a reading's line: "<label> <number><unit>" with the number within half a unit in its
// last place of `reference`, `decimals` places, and the line ending in `unit` exactly.
void expect_reading(const MeasurePanel& p, const std::string& label, double reference, int decimals,
                    const std::string& unit) {
    const std::string l = line_of(p, label);
    SCOPED_TRACE(l);
    ASSERT_GE(l.size(), unit.size());
    EXPECT_EQ(l.substr(l.size() - unit.size()), unit);
    const std::string number = l.substr(label.size(), l.size() - label.size() - unit.size());
    const double v = std::strtod(number.c_str(), nullptr);
    const std::size_t point = number.find('.');
    EXPECT_EQ(point == std::string::npos ? 0 : int(number.find_last_of("0123456789") - point), decimals);
    EXPECT_LE(std::fabs(v - reference), 0.5 * std::pow(10.0, -decimals) + 1e-12) << reference;
    if (v == 0) {
        EXPECT_EQ(number.find('-'), std::string::npos);
    }
}

world::GaugeReading triangle_at(double K) {
    world::GaugeReading r;
    r.kind = geo::Instrument::triangle, r.K = K;
    r.points[0] = {1, 1.5707963267948966}, r.points[1] = {1, 3.6651914291880923}, r.points[2] = {1, 5.7595865315812871};
    EXPECT_EQ(geo::measure_triangle(K, r.points, 3.14, r.triangle), geo::MeasureError::none);
    return r;
}
world::GaugeReading circle_at(double K, double rho) {
    world::GaugeReading r;
    r.kind = geo::Instrument::circle, r.K = K, r.radius = rho;
    EXPECT_EQ(geo::measure_circle(K, {}, rho, 3.14, r.circle), geo::MeasureError::none);
    return r;
}
world::GaugeReading parallels_at(double K) {
    world::GaugeReading r;
    r.kind = geo::Instrument::parallels, r.K = K, r.distance = 0.5, r.length = 1.5;
    EXPECT_EQ(geo::measure_parallels(K, 0.5, 1.5, r.parallels), geo::MeasureError::none);
    return r;
}
world::GaugeReading polygon_at(double K) {
    world::GaugeReading r;
    r.kind = geo::Instrument::polygon, r.K = K, r.sides = 3, r.around = 7, r.side = 1.2;
    EXPECT_EQ(geo::measure_polygon(K, 3, 7, 1.2, r.polygon), geo::MeasureError::none);
    return r;
}

TEST(MeasurePanel, ReadingsCarryTheirUnits) {
    for (double K : {-1.0, -0.3, 0.0, 0.4, 1.0}) {
        SCOPED_TRACE(K);
        const world::GaugeReading t = triangle_at(K);
        const MeasurePanel p = render::measure_panel(t);
        EXPECT_STREQ(p.text[0], "triangle");
        expect_reading(p, "A", t.triangle.angle_deg[0], 1, "°");
        expect_reading(p, "B", t.triangle.angle_deg[1], 1, "°");
        expect_reading(p, "C", t.triangle.angle_deg[2], 1, "°");
        expect_reading(p, "sum", t.triangle.sum_deg, 1, "°");
        expect_reading(p, "exc", t.triangle.excess_deg, 1, "°");
        expect_reading(p, "area", t.triangle.area, 3, " u²");
        expect_reading(p, "K*A", t.triangle.k_area_deg, 1, "°");

        const world::GaugeReading c = circle_at(K, 1);
        const MeasurePanel q = render::measure_panel(c);
        expect_reading(q, "r", 1, 3, " u");
        expect_reading(q, "C", c.circle.circumference, 3, " u");
        expect_reading(q, "C0", c.circle.flat_circumference, 3, " u");
        expect_reading(q, "C/C0", c.circle.circumference_ratio, 3, "");
        expect_reading(q, "A", c.circle.area, 3, " u²");
        expect_reading(q, "A0", c.circle.flat_area, 3, " u²");
        expect_reading(q, "A/A0", c.circle.area_ratio, 3, "");

        const world::GaugeReading l = parallels_at(K);
        const MeasurePanel m = render::measure_panel(l);
        expect_reading(m, "d", 0.5, 3, " u");
        expect_reading(m, "s", 1.5, 3, " u");
        expect_reading(m, "d(s)", l.parallels.distance, 3, " u");
        expect_reading(m, "ratio", l.parallels.ratio, 3, "");
        if (K > 0) expect_reading(m, "meet", l.parallels.meet_at, 3, " u");

        const world::GaugeReading g = polygon_at(K);
        const MeasurePanel n = render::measure_panel(g);
        expect_reading(n, "a", 1.2, 3, " u");
        expect_reading(n, "ang", g.polygon.angle_deg, 1, "°");
        expect_reading(n, g.polygon.gap_deg >= 0 ? "gap" : "over", std::fabs(g.polygon.gap_deg), 1, "°");
        expect_reading(n, "K", g.polygon.closing_K, 3, "");
    }
    // The flat triangle's excess is a rounding error's size and reads 0.0, unsigned.
    const world::GaugeReading flat = triangle_at(0);
    EXPECT_LT(std::fabs(flat.triangle.excess_deg), 1e-9);
    EXPECT_EQ(line_of(render::measure_panel(flat), "exc"), "exc    0.0°");
}

// (German labels: "Fl." for Fläche, "Exz" for Exzess.)
TEST(MeasurePanel, GermanUnitsAreLEAndFE) {
    const MeasurePanel p = render::measure_panel(triangle_at(1), lang::Language::de);
    expect_reading(p, "Fl.", triangle_at(1).triangle.area, 3, " FE");
    expect_reading(p, "Summe", triangle_at(1).triangle.sum_deg, 1, "°");
    const MeasurePanel q = render::measure_panel(circle_at(-1, 2), lang::Language::de);
    expect_reading(q, "r", 2, 3, " LE");
}

// Every line in every language within the panel's columns, every character drawn by the
// built-in font; large readings (a circle of radius 6, its area 113 at K = 0) too.
TEST(MeasurePanel, LinesFitAndAreDrawn) {
    for (lang::Language language : {lang::Language::en, lang::Language::de, lang::Language::fr})
        for (double K : {-1.0, 0.0, 1e-3, 1.0})
            for (const world::GaugeReading& r :
                 {triangle_at(K), circle_at(K, K > 0.5 ? 3 : 6), parallels_at(K), polygon_at(K)}) {
                const MeasurePanel p = render::measure_panel(r, language);
                EXPECT_GE(p.lines, 5);
                for (int i = 0; i < p.lines; ++i) {
                    const std::u32string l = decode(p.text[i]);
                    EXPECT_LE(l.size(), std::size_t(render::kPanelColumns)) << p.text[i];
                    for (char32_t c : l)
                        EXPECT_TRUE(render::builtin_font_draws(c)) << p.text[i] << " U+" << std::hex << unsigned(c);
                }
            }
}

// Drawn on the kiosk's 800x480 (both sides, the built-in font at twice its size), no pixel
// falls on the 480-pixel disc between x = 160 and 640, and some fall on each side.
TEST(MeasurePanel, FitsBesideTheDisc) {
    const int w = 800, h = 480;
    std::vector<uint32_t> pixels(w * h, 0);
    const render::Canvas c(pixels.data(), w, h, w * 4, render::PixelFormat::xrgb8888());
    const world::GaugeReading r = circle_at(0, 6);  // its longest lines
    render::HudInfo two;
    two.on = false, two.panels = 2;
    const render::HudLayout l = render::layout_hud(w, h, render::builtin_font(), two);
    ASSERT_EQ(l.disc, 480);
    render::draw_measure_panel(c, render::builtin_font(), render::measure_panel(r, lang::Language::de), l.panel[0], l.panel_scale);
    render::draw_measure_panel(c, render::builtin_font(), render::measure_panel(triangle_at(1), lang::Language::de), l.panel[1],
                               l.panel_scale);
    int left = 0, right = 0, disc = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (pixels[y * w + x] != 0) (x < 160 ? left : x >= 640 ? right : disc)++;
    EXPECT_EQ(disc, 0);
    EXPECT_GT(left, 0);
    EXPECT_GT(right, 0);
}

}  // namespace
}  // namespace noneuclid
