// The instruments in a world (world/instruments.hpp): the fixed engine's readings against the
// double engine's (within 0.05 degrees and 0.1%, the bounds, while K sweeps), the parts
// drawn where the readings say (the polygons closing exactly at the closing K, the rung as long
// as the parallels are apart), and the live instrument's marks where the ship was.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geometry/reference.hpp"
#include "test_common.hpp"
#include "world/world.hpp"

namespace noneuclid {
namespace {

using world::Action;
using world::GaugeReading;

world::Scene instruments_scene(double K) {
    world::Scene s;
    EXPECT_TRUE(world::builtin_scene("measure", {}, s));
    s.curvature = K;
    world::MeasureDecl circle, parallels, polygon;
    circle.kind = geo::Instrument::circle, circle.marks = {{0.7, 200}}, circle.radius = 0.9;
    parallels.kind = geo::Instrument::parallels, parallels.marks = {{1.1, 10}, {1.4, 60}}, parallels.length = 1.2;
    polygon.kind = geo::Instrument::polygon, polygon.marks = {{0.4, -60}};
    s.measures.push_back(circle), s.measures.push_back(parallels), s.measures.push_back(polygon);
    return s;
}

void near_relative(double a, double b, double rel, const std::string& what) {
    EXPECT_LE(std::fabs(a - b), rel * std::max(std::fabs(b), 1e-3)) << what << ": " << a << " against " << b;
}

// (Each frame against a double world built at the fixed world's K: the engines' clocks step K
// by different amounts, and the readings are compared at one K.)
TEST(Instruments, FixedReadingsWithinTheBoundsOfDoubleWhileKSweeps) {
    world::World<fx::fixed> f(instruments_scene(-1));
    f.press(Action::curvature_up);
    double worst_angle = 0, worst_rel = 0;
    for (int frame = 0; frame < 240; ++frame) {  // K from -1 to +1 at 0.5 a second
        const world::World<double> d(instruments_scene(static_cast<double>(f.K)));
        ASSERT_EQ(f.gauges().size(), d.gauges().size());
        for (std::size_t i = 0; i + 1 < f.gauges().size(); ++i) {
            const GaugeReading &a = f.gauges()[i].reading(), &b = d.gauges()[i].reading();
            ASSERT_EQ(a.error, geo::MeasureError::none) << i << " frame " << frame;
            ASSERT_EQ(b.error, geo::MeasureError::none) << i << " frame " << frame;
            const std::string what = std::string(geo::instrument_name(a.kind)) + " K " + std::to_string(b.K);
            auto rel = [&](double x, double y) {
                near_relative(x, y, 1e-3, what);
                worst_rel = std::max(worst_rel, std::fabs(x - y) / std::max(std::fabs(y), 1e-3));
            };
            auto angle = [&](double x, double y) {
                EXPECT_NEAR(x, y, 0.05) << what;
                worst_angle = std::max(worst_angle, std::fabs(x - y));
            };
            switch (a.kind) {
                case geo::Instrument::triangle:
                    for (int k = 0; k < 3; ++k) angle(a.triangle.angle_deg[k], b.triangle.angle_deg[k]), rel(a.triangle.side[k], b.triangle.side[k]);
                    angle(a.triangle.excess_deg, b.triangle.excess_deg), rel(a.triangle.area, b.triangle.area);
                    break;
                case geo::Instrument::circle:
                    rel(a.circle.circumference, b.circle.circumference), rel(a.circle.area, b.circle.area);
                    break;
                case geo::Instrument::parallels: rel(a.parallels.distance, b.parallels.distance); break;
                case geo::Instrument::polygon: angle(a.polygon.angle_deg, b.polygon.angle_deg), angle(a.polygon.gap_deg, b.polygon.gap_deg); break;
            }
        }
        f.step(1.0 / 60);
    }
    RecordProperty("worst_angle_deg", std::to_string(worst_angle));
    RecordProperty("worst_relative", std::to_string(worst_rel));
    std::printf("fixed against double: worst angle %.2e degrees, worst relative %.2e\n", worst_angle, worst_rel);
}

// The vertices of body `i` of a double world.
std::vector<geo::Polar<double>> vertices(const world::World<double>& w, std::size_t i) {
    std::vector<geo::Polar<double>> v(w.bodies[i].local.size());
    w.vertices(w.bodies[i], v.data());
    return v;
}

TEST(Instruments, PartsAreDrawnWhereTheReadingsSay) {
    const double closing = -0.82590178373293144;  // 7 triangles of side 1.2 (measure polygon)
    for (double K : {-1.0, closing, 0.0, 0.6}) {
        const world::World<double> w(instruments_scene(K));
        // The parts of each gauge follow its body order (world/instruments.hpp's GaugePart).
        std::size_t first = w.bodies.size();
        for (std::size_t g = w.gauges().size(); g-- > 0;) first -= static_cast<std::size_t>(world::gauge_body_count(w.scene().measures.size() > g ? w.scene().measures[g] : world::MeasureDecl{}));
        std::vector<std::size_t> base;
        for (std::size_t g = 0, at = first; g < w.gauges().size(); ++g) {
            base.push_back(at);
            at += static_cast<std::size_t>(world::gauge_body_count(g < w.scene().measures.size() ? w.scene().measures[g] : world::MeasureDecl{}));
        }
        // The triangle's vertices are its marks.
        const GaugeReading& t = w.gauges()[0].reading();
        const auto tv = vertices(w, base[0] + world::kTriangle);
        for (int k = 0; k < 3; ++k) EXPECT_LT(test::plane_distance(tv[k], t.points[k]), 1e-9) << K;
        // The rung is as long as the parallels are apart.
        const GaugeReading& p = w.gauges()[2].reading();
        const auto rung = vertices(w, base[2] + world::kRung);
        EXPECT_NEAR(geo::ref::distance(K, rung[0], rung[1]), p.parallels.distance, 1e-9) << K;
        // The polygons around their vertex: polygon q-1's last neighbour of the vertex meets
        // polygon 0's first exactly at the closing K, and only there.
        const world::MeasureDecl& pd = w.scene().measures[2];
        const auto first_polygon = vertices(w, base[3] + world::kPolygon0);
        const auto last_polygon = vertices(w, base[3] + world::kPolygon0 + static_cast<std::size_t>(pd.around) - 1);
        const std::size_t n1 = 1, n2 = static_cast<std::size_t>(pd.sides) - 1;  // the vertex's neighbours
        const double gap = std::min({geo::ref::distance(K, first_polygon[n1], last_polygon[n2]),
                                     geo::ref::distance(K, first_polygon[n2], last_polygon[n1])});
        if (K == closing) EXPECT_LT(gap, 1e-9) << K;
        else EXPECT_GT(gap, 1e-3) << K;
        EXPECT_LT(test::plane_distance(first_polygon[0], w.gauges()[3].reading().points[0]), 1e-9) << K;
    }
}

TEST(Instruments, TheLiveInstrumentTakesItsMarksWhereTheShipIs) {
    world::World<fx::fixed> w(instruments_scene(0));
    EXPECT_FALSE(w.measuring());
    w.press(Action::instrument);
    ASSERT_TRUE(w.measuring());
    EXPECT_EQ(w.gauges().back().kind(), geo::Instrument::triangle);
    const world::Body<fx::fixed>* ship = nullptr;
    for (const auto& b : w.bodies)
        if (b.desc->controlled) ship = &b;
    ASSERT_NE(ship, nullptr);
    std::vector<geo::Polar<double>> at;
    w.press(Action::thrust);
    for (int mark = 0; mark < 3; ++mark) {
        for (int i = 0; i < 40; ++i) w.step(1.0 / 60);
        w.press(Action::left);
        for (int i = 0; i < 30; ++i) w.step(1.0 / 60);
        w.release(Action::left);
        at.push_back({static_cast<double>(ship->centre.r), static_cast<double>(ship->centre.theta)});
        w.press(Action::fire), w.release(Action::fire);
        EXPECT_EQ(w.game().on(), false);
    }
    w.step(1.0 / 60);
    const GaugeReading& r = w.gauges().back().reading();
    ASSERT_FALSE(r.waiting);
    ASSERT_EQ(r.error, geo::MeasureError::none);
    for (int k = 0; k < 3; ++k) {  // the same Q16.16 numbers, read in double
        EXPECT_EQ(r.points[k].r, at[static_cast<std::size_t>(k)].r) << k;
        EXPECT_EQ(r.points[k].theta, at[static_cast<std::size_t>(k)].theta) << k;
    }
    // Cycled on: circle, parallels, polygon, then off.
    for (geo::Instrument next : {geo::Instrument::circle, geo::Instrument::parallels, geo::Instrument::polygon}) {
        w.press(Action::instrument);
        EXPECT_EQ(w.gauges().back().kind(), next);
    }
    w.press(Action::instrument);
    EXPECT_FALSE(w.measuring());
}

}  // namespace
}  // namespace noneuclid
