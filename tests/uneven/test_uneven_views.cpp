// The uneven world's two views and its scene files (src/uneven/draw.hpp, files/scene_file.cpp):
// the chart view without bumps is the constant-K world's stereographic picture point for point;
// the lens's middle square is seen twice from O and once in the chart; the fan behind the
// inhabitant's view follows the exponential map; [[bump]] tables, their refusals; the strength
// keys through a session.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "app/session.hpp"
#include "files/scene_file.hpp"
#include "geometry/edges.hpp"
#include "render/font.hpp"
#include "test_common.hpp"
#include "uneven/draw.hpp"
#include "world/world.hpp"

namespace {
namespace uneven_views_test {

using namespace noneuclid;
using uneven::Vec2;

constexpr double kPi = test::kPi;

struct Picture {
    std::vector<uint8_t> px;
    render::Canvas c;
    Picture(int w, int h) : px(static_cast<std::size_t>(w) * h * 4), c(px.data(), w, h, w * 4, render::PixelFormat::xrgb8888()) {}
};

// Without bumps every body's outline in the chart view is the constant-K world's: its vertices
// and edge points (World<double>, geo::edge_points) through the stereographic projection, within
// 0.05 px, at three K (bodies wholly inside the limit circle, so that none is clipped).
TEST(UnevenViews, TheChartWithoutBumpsIsTheStereographicView) {
    for (double K : {-1.0, 0.0, 0.6}) {
        world::Scene s;
        ASSERT_TRUE(world::builtin_scene("kiosk", {}, s));
        s.curvature = K;
        const world::World<double> c(s);
        uneven::World u(s);
        uneven::Drawing d;
        d.prepare(u);
        Picture p(800, 480);
        render::DrawOptions o;
        o.projection = geo::Projection::stereographic;
        d.draw(p.c, u, o, true);
        const auto m = geo::ScreenMap<double>::of(800, 480, K, s.limit_radius, geo::Projection::stereographic);
        double worst = 0;
        int bodies = 0;
        for (std::size_t i = 0; i < u.bodies.size(); ++i) {  // (the constant-K world's instruments follow)
            const auto& b = c.bodies[i];
            if (b.desc->grid || b.local.size() < 3) continue;
            std::vector<geo::Polar<double>> v(b.local.size());
            c.vertices(b, v.data());
            std::vector<geo::SubPoint> want;
            bool inside = true;
            for (std::size_t e = 0; e < v.size(); ++e)
                geo::edge_points(K, v[e], v[(e + 1) % v.size()], b.desc->tessellation, [&](int k, geo::Polar<double> q) {
                    if (k == 0 && e > 0) return;
                    const double rho = geo::project(K, q.r, geo::Projection::stereographic).rho;
                    const double x = m.cx + m.scale * rho * std::cos(q.theta), y = m.cy - m.scale * rho * std::sin(q.theta);
                    inside = inside && std::hypot(x - m.cx, y - m.cy) < m.rim - 2;
                    want.push_back(geo::to_sub(x, y));
                });
            if (!inside) continue;
            const std::vector<geo::SubPoint>& got = d.outline(i);
            ASSERT_GE(got.size(), want.size());
            ++bodies;
            for (std::size_t k = 0; k < want.size(); ++k)
                worst = std::fmax(worst, std::hypot(got[k].x - want[k].x, got[k].y - want[k].y) / geo::kSub);
        }
        std::printf("K = %+.1f: %d bodies' outlines within %.4f px of the stereographic view\n", K, bodies, worst);
        EXPECT_GE(bodies, 3) << K;
        EXPECT_LT(worst, 0.05) << K;
    }
}

// The connected regions of one colour in a picture (8-neighbours: a line's pixels touch diagonally), of at least `least` pixels.
int regions(const render::Canvas& c, render::Rgb colour, int least) {
    std::vector<char> seen(static_cast<std::size_t>(c.width()) * c.height(), 0);
    std::vector<int> stack;
    int count = 0;
    for (int start = 0; start < c.width() * c.height(); ++start) {
        if (seen[start] || !(c.get(start % c.width(), start / c.width()) == colour)) continue;
        int size = 0;
        stack.assign(1, start);
        seen[start] = 1;
        while (!stack.empty()) {
            const int at = stack.back();
            stack.pop_back();
            ++size;
            const int x = at % c.width(), y = at / c.width();
            const int next[8][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1},
                                    {x + 1, y + 1}, {x - 1, y - 1}, {x - 1, y + 1}, {x + 1, y - 1}};
            for (const auto& n : next) {
                if (!c.contains(n[0], n[1])) continue;
                const int i = n[1] * c.width() + n[0];
                if (!seen[i] && c.get(n[0], n[1]) == colour) seen[i] = 1, stack.push_back(i);
            }
        }
        count += size >= least;
    }
    return count;
}

// The lens: the middle square, straight behind the mass from O, makes one outline in the chart
// and two (or more: the mass's ring) in the inhabitant's view; without the mass, one in both.
TEST(UnevenViews, TheLensShowsTheSquareBehindItTwice) {
    world::Scene s;
    ASSERT_TRUE(world::builtin_scene("lens", {}, s));
    const render::Rgb blue{120, 160, 255};  // square 3's
    for (bool mass : {true, false}) {
        if (!mass) s.bumps[0].strength = 0;
        for (bool chart : {true, false}) {
            app::SessionOptions so;
            so.hud = false;
            so.draw.projection = chart ? geo::Projection::stereographic : geo::Projection::azimuthal_equidistant;
            kinds::KindChoice kind;
            std::string why;
            ASSERT_TRUE(kinds::choose_kind(s, nullptr, kind, why)) << why;
            ASSERT_STREQ(kinds::kind_name(kind.kind), "uneven");
            const auto session = app::make_session(kind, s, so, render::builtin_font(), nullptr);
            Picture p(800, 480);
            session->draw(p.c);
            const int n = regions(p.c, blue, 12);
            std::printf("%s, %s view: square 3 seen %d times\n", mass ? "with the mass" : "without", chart ? "chart" : "inhabitant's", n);
            if (mass && !chart) EXPECT_GE(n, 2);
            else EXPECT_EQ(n, 1);
        }
    }
}

// The fan the inhabitant's view is drawn from: interpolated, within 0.5 px (of the chart view)
// of the exponential map traced finely, wherever the view shows the world within the limit
// radius of O.
TEST(UnevenViews, TheFanFollowsTheExponentialMap) {
    for (const char* name : {"lens", "hills"})
        for (double K : {-1.0, 0.0, 0.7}) {
            world::Scene s;
            ASSERT_TRUE(world::builtin_scene(name, {}, s));
            s.curvature = K;
            uneven::World u(s);
            uneven::Drawing d;
            d.prepare(u);
            Picture p(800, 480);
            render::DrawOptions o;
            d.draw(p.c, u, o, true);  // the inhabitant's view: the fan is built
            const auto m = geo::ScreenMap<double>::of(800, 480, K, s.limit_radius, geo::Projection::stereographic);
            std::mt19937 rng(7);
            std::uniform_real_distribution<double> unit(0, 1);
            double worst = 0, wa = 0, wt = 0, wr = 0;
            for (int i = 0; i < 400; ++i) {
                const double a = 2 * kPi * unit(rng), step = 2 * kPi / uneven::kFanRays;
                // (within the reach of both rays either side, and the limit radius: past it, where a
                // hill has held a ray in, neighbouring rays part too far for a straight line between)
                const double reach = std::fmin(std::fmin(d.fan_reach(a - step), d.fan_reach(a + step)), u.limit());
                const double t = reach * unit(rng);
                const Vec2 want = uneven::exp_map(u.metric(), {0, 0}, a, t).x, got = d.fan_point(t, a);
                const double e = m.scale * std::hypot(want.x - got.x, want.y - got.y);
                if (e > worst) worst = e, wa = a, wt = t, wr = reach;
            }
            std::printf("%s at K = %+.1f: the fan within %.3f px of the exponential map (worst at %.1f deg, %.3f of %.3f)\n",
                        name, K, worst, wa * 180 / kPi, wt, wr);
            EXPECT_LT(worst, 0.5) << name << " " << K;
        }
}

std::string refused(const std::string& text) {
    world::Scene s;
    files::SceneError e;
    return files::parse_scene(text, "t.toml", s, e) ? "" : e.message;
}

TEST(UnevenViews, BumpTablesAndTheirRefusals) {
    world::Scene s;
    files::SceneError e;
    ASSERT_TRUE(files::parse_scene("curvature = -0.5\nstrength_rate = 0.25\n[[bump]]\nkind = \"mass\"\ncentre = [1, 30]\n"
                                   "width = 0.2\nstrength = 0.4\n[[bump]]\nkind = \"hill\"\nstrength = -1\n",
                                   "t.toml", s, e))
        << e.to_string();
    ASSERT_EQ(s.bumps.size(), 2u);
    EXPECT_TRUE(s.bumps[0].mass);
    EXPECT_EQ(s.bumps[0].r, 1);
    EXPECT_EQ(s.bumps[0].theta_deg, 30);
    EXPECT_EQ(s.bumps[0].width, 0.2);
    EXPECT_EQ(s.bumps[1].strength, -1);
    EXPECT_EQ(s.strength_rate, 0.25);
    const std::string bump = "[[bump]]\nkind = \"hill\"\n";
    const struct {
        std::string text, says;
    } bad[] = {
        {"[[bump]]\nkind = \"dip\"\n", "expected kind = \"hill\" or \"mass\", found \"dip\""},
        {bump + "width = 0\n", "width = 0 is outside 0.1 to 3"},
        {bump + "width = -1\n", "width = -1 is outside 0.1 to 3"},
        {bump + "strength = 2\n", "strength = 2 is outside -1.5 to 1.5"},
        {"[[bump]]\nkind = \"mass\"\nstrength = 1\n", "strength = 1 is outside -0.9 to 0.9 (a mass's cone closes up at 1)"},
        {bump + "centre = [3, 0]\n", "its centre at r = 3 is outside the world"},
        {"limit_radius = 1\n" + bump + "centre = [1.5, 0]\n", "its centre at r = 1.5 is outside the world, which reaches 1"},
        {bump + "shape = 1\n", "shape"},
        {"curvature = 1\n[[body]]\nname = \"far\"\nposition = [3, 0]\nvertices = [[0.1, 0]]\n" + bump,
         "body 'far': at r = 3 it lies past 2.094"},
        {"[[measure]]\ninstrument = \"circle\"\n" + bump, "a scene with bumps measures triangles only (src/uneven): remove the [[measure]] circle, or the bumps"},
    };
    for (const auto& b : bad) {
        const std::string said = refused(b.text);
        EXPECT_NE(said.find(b.says), std::string::npos) << b.text << "\nsaid: " << said;
    }
    std::string nine;
    for (int i = 0; i < 9; ++i) nine += bump;
    EXPECT_NE(refused(nine).find("at most 8 bumps"), std::string::npos) << refused(nine);
}

// Strength up held for a second: the gain grows by the scene's rate (0.5 a second), every bump's
// strength with it, and the recording of the same presses replays it; strength down stops at 0.
TEST(UnevenViews, TheStrengthKeysTurnEveryBump) {
    world::Scene s;
    ASSERT_TRUE(world::builtin_scene("hills", {}, s));
    uneven::World w(s);
    w.press(world::Action::strength_up);
    for (int i = 0; i < 60; ++i) w.step(1.0 / 60);
    w.release(world::Action::strength_up);
    EXPECT_NEAR(w.gain(), 1.5, 1e-12);
    for (int i = 0; i < w.metric().bump_count; ++i) EXPECT_NEAR(w.metric().bumps[i].strength, 1.5 * s.bumps[i].strength, 1e-12);
    w.press(world::Action::strength_down);
    for (int i = 0; i < 240; ++i) w.step(1.0 / 60);
    EXPECT_EQ(w.gain(), 0);
    EXPECT_EQ(w.metric().curvature({0.5, 0.5}), 0);  // flat, as the scene's K
    // The most: a hill of 0.8 reaches 1.5 at 1.875.
    w.release(world::Action::strength_down), w.press(world::Action::strength_up);
    for (int i = 0; i < 600; ++i) w.step(1.0 / 60);
    EXPECT_NEAR(w.gain(), 1.5 / 0.8, 1e-12);
}

}  // namespace uneven_views_test
}  // namespace
