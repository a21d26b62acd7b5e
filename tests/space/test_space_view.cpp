// The three-dimensional world on the screen (src/space/edges.hpp, space/draw.hpp) against the
// tests' own: the apparent size of a ball by its closed form, sin a = S_K(rho) / S_K(d) (the
// right triangle eye, centre, tangent point in the plane through them), measured on drawn pixels;
// and every piece of a drawn edge against the edge's true image, the geodesic of the 4-vector
// embedding in long double seen through the embedding's own directions (the tangent at the eye
// toward each point, (X - C_K(d) E) / S_K(d)), in the inhabitant's view and in the map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "embedding.hpp"
#include "space/draw.hpp"

namespace {
namespace space_view_test {

using namespace noneuclid;
using namespace space_embedding;

// (The embedding's distance, under the name this file uses.)
LD distance(LD K, R4 P, R4 Q) { return ref_distance(K, P, Q); }
LD dotl(V3<LD> a, V3<double> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// A point of the geodesic from p to q, a fraction t of the way, in the embedding (K != 0), and
// its (r, u) (the map's position r u).
struct TruePoint {
    R4 X;
    LD r;
    V3<LD> u;
};
TruePoint along(LD K, const Point<double>& p, const Point<double>& q, LD t) {
    TruePoint out;
    if (K == 0) {
        const V3<double> a = space::map_position(p), b = space::map_position(q);
        const V3<LD> m{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
        out.r = std::sqrt(m.x * m.x + m.y * m.y + m.z * m.z);
        out.u = {m.x / out.r, m.y / out.r, m.z / out.r};
        out.X = {1, m.x, m.y, m.z};
        return out;
    }
    const R4 P = embed(K, p), Q = embed(K, q);
    const LD L = distance(K, P, Q);
    const R4 V = (1 / S(K, L)) * (Q - C(K, L) * P);
    out.X = C(K, t * L) * P + S(K, t * L) * V;
    const R4 O{1, 0, 0, 0};
    out.r = distance(K, O, out.X);
    const LD s = std::sqrt(out.X.x * out.X.x + out.X.y * out.X.y + out.X.z * out.X.z);
    out.u = {out.X.x / s, out.X.y / s, out.X.z / s};
    return out;
}

// Where the eye sees a true point: the carried direction of the geodesic's tangent toward it.
struct Px {
    LD x, y;
    bool front;
};
Px seen_by_eye(LD K, const Point<double>& eye, const space::Frame<double>& f, const space::Lens& lens, const TruePoint& X) {
    V3<LD> d;
    if (K == 0) {
        const V3<double> e = space::map_position(eye);
        d = {X.X.x - e.x, X.X.y - e.y, X.X.z - e.z};
    } else {
        const R4 E = embed(K, eye);
        const LD D = distance(K, E, X.X);
        d = carried(K, E, (1 / S(K, D)) * (X.X - C(K, D) * E));
    }
    const LD z = dotl(d, f.forward), n = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return {lens.cx + lens.focal * dotl(d, f.right) / z, lens.cy - lens.focal * dotl(d, f.up) / z, z > 0.05L * n};
}
Px seen_in_map(const space::MapView<double>& m, const TruePoint& X) {
    const V3<LD> v{X.r * X.u.x - m.camera.x, X.r * X.u.y - m.camera.y, X.r * X.u.z - m.camera.z};
    const LD z = dotl(v, m.frame.forward);
    return {m.lens.cx + m.lens.focal * dotl(v, m.frame.right) / z, m.lens.cy - m.lens.focal * dotl(v, m.frame.up) / z,
            z > 0 && X.r <= m.limit};
}

struct Segment {
    double x0, y0, x1, y1;
};
double to_segments(const std::vector<Segment>& s, LD x, LD y) {
    double best = 1e300;
    for (const Segment& g : s) {
        const double dx = g.x1 - g.x0, dy = g.y1 - g.y0, l2 = dx * dx + dy * dy;
        double t = l2 > 0 ? ((x - g.x0) * dx + (y - g.y0) * dy) / l2 : 0;
        t = std::clamp(t, 0.0, 1.0);
        best = std::min(best, static_cast<double>(std::hypot(x - (g.x0 + t * dx), y - (g.y0 + t * dy))));
    }
    return best;
}

constexpr double kKs[] = {-1, -0.5, 0, 0.5, 1};
constexpr int kW = 800, kH = 480;
const space::Lens kLens{kW / 2.0, kH / 2.0, 400};

// The largest distance from the screen's centre of a lit pixel's centre.
double lit_radius(const std::vector<uint32_t>& px) {
    double most = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            if (px[static_cast<std::size_t>(y) * kW + x] != 0) most = std::max(most, std::hypot(x + 0.5 - kLens.cx, y + 0.5 - kLens.cy));
    return most;
}

// A ball of radius rho about c drawn as 48 meridians of 96 geodesic edges each, its poles on
// the line from O through c.
void draw_ball(const render::Canvas& canvas, const space::InhabitantView<double>& view, double K, const Point<double>& c,
               double rho) {
    const space::EdgeStyle style;
    for (int m = 0; m < 48; ++m) {
        const double phi = 2 * 3.14159265358979323846 * m / 48;
        Point<double> prev;
        for (int i = 0; i <= 96; ++i) {
            const double th = 3.14159265358979323846 * i / 96;
            // (c lies on the x axis: its carried frame is the frame at O.)
            const V3<double> w{std::cos(th), std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi)};
            const Point<double> p = space::walk(K, c, w, rho).end;
            if (i > 0) space::draw_edge(canvas, view, K, prev, p, style);
            prev = p;
        }
    }
}

TEST(SpaceView, ABallLooksAsLargeAsItsClosedFormOnTheDrawnPixels) {
    const double d = 1.2, rho = 0.35;
    for (const double K : kKs) {
        std::vector<uint32_t> px(kW * kH, 0);
        const render::Canvas canvas(px.data(), kW, kH, kW * 4, render::PixelFormat::xrgb8888());
        space::InhabitantView<double> view;
        view.K = K, view.lens = kLens;  // the eye at O facing +x
        const Point<double> c{d, {1, 0, 0}};
        draw_ball(canvas, view, K, c, rho);
        const LD alpha = std::asin(S(K, rho) / S(K, d));
        const double want = static_cast<double>(kLens.focal * std::tan(alpha));
        const double got = lit_radius(px);
        EXPECT_NEAR(got, want, 1.0) << "K = " << K;
        std::printf("K = %+.1f: the ball's drawn radius %.2f px, its closed form %.2f px\n", K, got, want);
        if (K == 1) RecordProperty("ball_radius_px_K1", std::to_string(got) + " for " + std::to_string(want));
    }
}

// In S³ the same ball is seen the other way round too: behind the eye, light having come through
// the antipode, at the angular size of distance 2 pi / sqrt K - d, which the sine makes equal.
TEST(SpaceView, InS3TheBallIsSeenBehindTheEyeTheSameSize) {
    const double K = 1, d = 1.2, rho = 0.35;
    std::vector<uint32_t> px(kW * kH, 0);
    const render::Canvas canvas(px.data(), kW, kH, kW * 4, render::PixelFormat::xrgb8888());
    space::InhabitantView<double> view;
    view.K = K, view.lens = kLens, view.around = true;
    view.frame.forward = {-1, 0, 0}, view.frame.right = {0, 1, 0};  // (up stays z: right = forward x up)
    draw_ball(canvas, view, K, Point<double>{d, {1, 0, 0}}, rho);
    const double want = static_cast<double>(kLens.focal * std::tan(std::asin(S(K, rho) / std::fabs(S(K, 2 * 3.14159265358979323846L - d)))));
    EXPECT_NEAR(lit_radius(px), want, 1.0);
}

// Random edges seen from random eyes, facing random ways, and in the orbiting map: every piece's
// ends lie within 1 px of the true image, and every true point on the screen within 1 px of a
// piece.
TEST(SpaceView, EveryDrawnEdgeIsWithinAPixelOfItsTrueImage) {
    std::mt19937_64 rng(20261207);
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(0, 1);
    auto direction = [&] { return space::unit(V3<double>{n(rng), n(rng), n(rng)}); };
    double worst_piece = 0, worst_true = 0;
    int pieces = 0;
    for (const double K : kKs)
        for (int i = 0; i < 60; ++i) {
            const double reach = K > 0 ? 2.5 / std::sqrt(K) : 2.5;
            const Point<double> p{reach * u(rng), direction()}, q{reach * u(rng), direction()};
            std::vector<Segment> drawn;
            auto collect = [&](const space::Seen& a, const space::Seen& b) { drawn.push_back({a.x, a.y, b.x, b.y}); };
            space::InhabitantView<double> eye;
            space::MapView<double> map = space::orbit_camera(reach, 2.6 * reach, 6.28 * u(rng), u(rng) - 0.5,
                                                             space::Lens{kW / 2.0, kH / 2.0, kH * 1.1});
            const bool in_map = i % 2 == 1;
            if (!in_map) {
                eye.K = K, eye.lens = kLens, eye.eye = {0.8 * reach * u(rng), direction()};
                const V3<double> f = direction(), up = space::unit(direction() - space::dot(direction(), f) * f);
                eye.frame.forward = f, eye.frame.up = space::unit(up - space::dot(up, f) * f);
                eye.frame.right = space::cross(eye.frame.forward, eye.frame.up);
                space::edge_pieces(eye, K, p, q, 0.1, collect);
            } else {
                space::edge_pieces(map, K, p, q, 0.1, collect);
            }
            std::vector<Px> truth;
            for (int k = 0; k <= 2000; ++k) {
                const TruePoint X = along(K, p, q, k / 2000.0L);
                truth.push_back(in_map ? seen_in_map(map, X) : seen_by_eye(K, eye.eye, eye.frame, kLens, X));
            }
            auto on_screen = [](const Px& s) { return s.front && std::fabs(s.x - kW / 2.0) < kW && std::fabs(s.y - kH / 2.0) < kH; };
            std::vector<Segment> true_curve;  // (the 2001 true points joined where both are shown)
            for (std::size_t k = 1; k < truth.size(); ++k)
                if (truth[k - 1].front && truth[k].front)
                    true_curve.push_back({static_cast<double>(truth[k - 1].x), static_cast<double>(truth[k - 1].y),
                                          static_cast<double>(truth[k].x), static_cast<double>(truth[k].y)});
            for (const Segment& s : drawn) {
                for (const auto& [x, y] : {std::pair{s.x0, s.y0}, std::pair{s.x1, s.y1}}) {
                    if (std::fabs(x - kW / 2.0) > kW || std::fabs(y - kH / 2.0) > kH) continue;  // (off the screen)
                    worst_piece = std::max(worst_piece, to_segments(true_curve, x, y));
                }
                ++pieces;
            }
            for (std::size_t k = 0; k < truth.size(); k += 10)
                if (on_screen(truth[k]) && !drawn.empty()) worst_true = std::max(worst_true, to_segments(drawn, truth[k].x, truth[k].y));
        }
    EXPECT_GT(pieces, 200);
    EXPECT_LT(worst_piece, 1.0);
    EXPECT_LT(worst_true, 1.0);
    RecordProperty("worst_piece_px", std::to_string(worst_piece));
    RecordProperty("worst_true_px", std::to_string(worst_true));
    std::printf("edges: %d pieces; worst piece end %.3f px from the true image, worst true point %.3f px from a piece\n",
                pieces, worst_piece, worst_true);
}

}  // namespace space_view_test
}  // namespace
