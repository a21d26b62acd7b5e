// Filled and textured bodies (render/fill.hpp) against an independent reference, for K in
// {-1, -0.3, 0, 0.3, 1}, in double and in fixed point.
//
// The reference takes each pixel centre back another way: the equidistant view's inverse in
// polar form (r = |(X, Y)|, theta = atan2), the GLM model of geometry/reference.hpp (std::
// functions, a textbook branch per sign of K) into the body's own frame, and there the
// gnomonic chart, where the outline is a straight polygon and PNPOLY decides, in long double
// (as tests/geometry/test_collision.cpp does). A pixel whose centre is farther from the outline
// than the engine's tolerance (its margin: the geodesic distance to the nearest edge, by a
// ternary search) must be lit exactly when the reference says it is inside. The texture's
// coordinates are the same point's local equidistant coordinates, read off the reference's
// local polar form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "../geometry/chart_reference.hpp"
#include "coordinate_image.hpp"
#include "geometry/local_frame.hpp"
#include "geometry/reference.hpp"
#include "render/draw_world.hpp"
#include "render/parallel_frame.hpp"
#include "test_common.hpp"

using namespace noneuclid;
using geo::Polar;
using fx::fixed;

namespace {

using noneuclid::test::kPi;
using noneuclid::test::deg;
const double kCurvatures[] = {-1, -0.3, 0, 0.3, 1};
constexpr int kW = 400, kH = 400;

// ---- bodies ----------------------------------------------------------------------------------

struct Shape {
    const char* name;
    std::vector<Polar<double>> local;  // rho, phi in radians
};
Shape star_shape() {  // an asteroid: star-shaped about its centre
    const double rho[] = {0.4, 0.33, 0.38, 0.3, 0.4, 0.36, 0.31, 0.39, 0.34, 0.37};
    Shape s{"star", {}};
    for (int i = 0; i < 10; ++i) s.local.push_back({rho[i], 2 * kPi * i / 10});
    return s;
}
Shape c_shape() {  // a thick C: its centre lies outside it, so it is not star-shaped about it
    Shape s{"C", {}};
    for (double phi : {40, 90, 140, 180, 220, 270, 320}) s.local.push_back({0.4, deg(phi)});
    for (double phi : {300, 240, 180, 120, 60}) s.local.push_back({0.2, deg(phi)});
    return s;
}
Shape bowtie_shape() {  // its edges cross: even-odd
    Shape s{"bowtie", {}};
    for (double phi : {30, 150, 210, 330}) s.local.push_back({0.35, deg(phi)});
    return s;
}

struct Place {
    double r, theta_deg, facing_deg;
};
world::Scene scene_of(const Shape& s, Place p, double K, std::shared_ptr<const world::Image> texture = nullptr,
                      bool bilinear = false, double texture_scale = 1) {
    world::Scene sc;
    sc.curvature = K;
    world::SceneBody b;
    b.name = s.name;
    for (const Polar<double>& v : s.local) b.vertices.push_back({v.r, v.theta * 180 / kPi});
    b.r = p.r, b.theta_deg = p.theta_deg, b.facing_deg = p.facing_deg;
    b.filled = true, b.fill = {255, 255, 255};
    b.texture = std::move(texture), b.texture_bilinear = bilinear, b.texture_scale = texture_scale;
    sc.bodies.push_back(b);
    return sc;
}

// The fill alone (no backdrop, no outline) of body 0 on a black XRGB8888 canvas.
template <class T>
struct Render {
    std::vector<uint8_t> px = std::vector<uint8_t>(kW * kH * 4, 0);
    render::Canvas c{px.data(), kW, kH, kW * 4, render::PixelFormat::xrgb8888()};
    render::Rgb at(int x, int y) const { return c.get(x, y); }
};
template <class T>
void fill_once(world::World<T>& w, render::DrawScratch<T>& s, Render<T>& out, bool aa) {
    render::DrawOptions o;
    o.antialias = aa;
    const auto m = render::ScreenMap<T>::of(out.c, w.K, w.R, o.projection);
    std::fill(out.px.begin(), out.px.end(), 0);
    s.fill.begin_frame(out.c);
    const render::FillJob* j = s.fill.plan(w, 0, m, o, kW, kH);
    ASSERT_NE(j, nullptr);
    render::fill_rows(out.c, *j, 0, kH, s.fill.work[0]);
}

// ---- the reference ---------------------------------------------------------------------------

using test::P2;
using test::pnpoly;
using test::TK;
struct Reference {
    double K;
    Shape shape;
    Place place;
    double scale;  // px per world unit
    glm::dmat3 to_local, from_local;
    std::vector<P2> poly;  // the outline in the gnomonic chart about the centre
    Reference(double K_, Shape s, Place p, double scale_) : K(K_), shape(std::move(s)), place(p), scale(scale_) {
        to_local = geo::ref::Rot(-facing()) * geo::ref::frame_inverse(K, centre());
        from_local = geo::ref::frame(K, centre()) * geo::ref::Rot(facing());
        for (const Polar<double>& v : shape.local) poly.push_back({TK(K, v.r) * std::cos(v.theta), TK(K, v.r) * std::sin(v.theta)});
    }
    Polar<double> centre() const { return {place.r, deg(place.theta_deg)}; }
    double facing() const { return deg(place.facing_deg); }
    // The point at chart coordinates (u, v).
    Polar<double> from_chart(double u, double v) const {
        const double w = 1 / std::sqrt(1 + K * (u * u + v * v));
        return geo::ref::polar(K, from_local * glm::dvec3(w, u * w, v * w));
    }
    // The pixels the body can light: its outline's screen box (each edge at 256 points) and two
    // pixels more; the whole canvas when it holds the antipode (on the sphere).
    void box(int& x0, int& y0, int& x1, int& y1) const {
        x0 = y0 = 1 << 30, x1 = y1 = -(1 << 30);
        if (K > 0 && inside({kPi / std::sqrt(K), 0})) {
            x0 = y0 = 0, x1 = kW - 1, y1 = kH - 1;
            return;
        }
        for (std::size_t i = 0; i < poly.size(); ++i)
            for (int k = 0; k < 256; ++k) {
                const P2 a = poly[i], b = poly[(i + 1) % poly.size()];
                const double t = k / 256.0;
                const Polar<double> q = from_chart(static_cast<double>(a.u + t * (b.u - a.u)), static_cast<double>(a.v + t * (b.v - a.v)));
                const double x = kW / 2.0 + scale * q.r * std::cos(q.theta), y = kH / 2.0 - scale * q.r * std::sin(q.theta);
                x0 = std::min(x0, static_cast<int>(std::floor(x)) - 2), x1 = std::max(x1, static_cast<int>(std::floor(x)) + 2);
                y0 = std::min(y0, static_cast<int>(std::floor(y)) - 2), y1 = std::max(y1, static_cast<int>(std::floor(y)) + 2);
            }
        x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, kW - 1), y1 = std::min(y1, kH - 1);
    }
    // The shown disc's radius, px (docs/rendering.md): the limit circle, and on the sphere at
    // most 1 px inside the antipode's circle.
    double clip() const {
        const double rim = std::min(kW, kH) / 2.0;
        return K > 0 ? std::min(rim, scale * kPi / std::sqrt(K) - 1.0) : rim;
    }
    // The pixel centre's distance from the view's centre, px.
    static double from_centre(int x, int y) { return std::hypot(x + 0.5 - kW / 2.0, y + 0.5 - kH / 2.0); }
    // The pixel centre's point, or false outside the shown disc (nothing is drawn there).
    bool point(int x, int y, Polar<double>& q) const {
        const double X = (x + 0.5 - kW / 2.0) / scale, Y = (kH / 2.0 - y - 0.5) / scale;
        q = {std::hypot(X, Y), std::atan2(Y, X)};
        return from_centre(x, y) < clip() && !(K > 0 && q.r >= kPi / std::sqrt(K));
    }
    glm::dvec3 local(Polar<double> q) const { return to_local * geo::ref::point(K, q); }
    bool inside(Polar<double> q) const {
        const glm::dvec3 l = local(q);
        if (l.x <= 0) return false;
        return pnpoly(poly, {static_cast<long double>(l.y) / l.x, static_cast<long double>(l.z) / l.x});
    }
    // The geodesic distance from q to the outline: the nearest edge, each by a ternary search
    // along it (the edge from vertex a to b is the chart's straight segment).
    double margin(Polar<double> q) const {
        double best = 1e9;
        const std::size_t n = poly.size();
        for (std::size_t i = 0; i < n; ++i) {
            const double au = static_cast<double>(poly[i].u), av = static_cast<double>(poly[i].v);
            const double bu = static_cast<double>(poly[(i + 1) % n].u), bv = static_cast<double>(poly[(i + 1) % n].v);
            auto at = [&](double t) { return geo::ref::distance(K, q, from_chart(au + t * (bu - au), av + t * (bv - av))); };
            double lo = 0, hi = 1;
            for (int k = 0; k < 80; ++k) {
                const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
                if (at(m1) < at(m2)) hi = m2;
                else lo = m1;
            }
            best = std::min(best, at((lo + hi) / 2));
        }
        return best;
    }
    // The texture coordinates (texels) of q: its local equidistant coordinates, scaled so that
    // `width` texels span `scale_d` diameters of the body, the image's middle at the centre.
    void texcoord(Polar<double> q, int width, int height, double scale_d, double& s, double& t) const {
        const glm::dvec3 l = local(q);
        const Polar<double> p = geo::ref::polar(K, l);
        double rho = 0;
        for (const Polar<double>& v : shape.local) rho = std::max(rho, v.r);
        const double k = width / (scale_d * 2 * rho);
        s = width / 2.0 + p.r * std::cos(p.theta) * k, t = height / 2.0 - p.r * std::sin(p.theta) * k;
    }
};

// The engines' tolerances, world units: double's the rounding of its arithmetic; fixed point's
// what its vertices and the pixel's way back (Q16.16, tables) may be off, measured (the
// largest margin of a pixel found wrong, at K = -1 toward the limit circle) and doubled.
double tolerance(double K, double r, bool fixed_point) {
    if (!fixed_point) return 1e-9;
    return K <= -0.6 && r > 2.5 ? 8e-3 : 2e-3;
}

struct Count {
    long lit = 0, inside = 0, wrong = 0;
    double worst_margin = 0;  // of a pixel found wrong
};
template <class T>
Count check_coverage(const Shape& shape, Place p, double K, bool aa) {
    world::World<T> w(scene_of(shape, p, K));
    render::DrawScratch<T> s;
    s.prepare(w);
    Render<T> out;
    fill_once(w, s, out, aa);
    const Reference ref(K, shape, p, kW / 2.0 / static_cast<double>(w.R));
    int bx0, by0, bx1, by1;
    ref.box(bx0, by0, bx1, by1);
    Count n;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (x < bx0 || x > bx1 || y < by0 || y > by1) {  // beyond the outline's box: dark
                EXPECT_EQ(out.at(x, y).r, 0) << shape.name << " K " << K << " r " << p.r << ": pixel " << x << "," << y;
                continue;
            }
            // (The engine's clip circle is held in 1/256 px: a centre within 1/128 px of it may
            // fall either side.)
            if (std::abs(Reference::from_centre(x, y) - ref.clip()) < 1.0 / 128) continue;
            Polar<double> q;
            const bool in = ref.point(x, y, q) && ref.inside(q);
            const int v = out.at(x, y).r;
            const bool lit = aa ? v >= 128 : v == 255;
            if (!aa) {
                EXPECT_TRUE(v == 0 || v == 255) << x << "," << y;
            }
            n.lit += lit, n.inside += in;
            if (lit == in) continue;
            if (Reference::from_centre(x, y) >= ref.clip()) {  // outside the shown disc: never drawn
                ADD_FAILURE() << shape.name << " K " << K << " r " << p.r << ": pixel " << x << "," << y << " lit outside the shown disc";
                continue;
            }
            const double m = ref.margin(q);
            n.worst_margin = std::max(n.worst_margin, m);
            ++n.wrong;
            EXPECT_LT(m, tolerance(K, p.r, std::is_same_v<T, fixed>))
                << shape.name << " at r " << p.r << " K " << K << ": pixel " << x << "," << y << " lit " << lit
                << " but inside " << in;
        }
    return n;
}

const Place kPlaces[] = {{0, 0, 20}, {0.9, 30, 200}, {1.8, 200, 75}, {2.7, 300, 10}};

template <class T>
void coverage_everywhere(bool aa) {
    for (const Shape& shape : {star_shape(), c_shape(), bowtie_shape()})
        for (double K : kCurvatures)
            for (Place p : kPlaces) {
                const Count n = check_coverage<T>(shape, p, K, aa);
                EXPECT_GT(n.inside, 300) << shape.name << " K " << K << " r " << p.r;
                ::testing::Test::RecordProperty(std::string(shape.name) + (aa ? "_aa" : "") + "_K" + std::to_string(K) + "_r" +
                                   std::to_string(p.r) + "_wrong",
                               std::to_string(n.wrong) + " of " + std::to_string(n.inside) + ", margin " +
                                   std::to_string(n.worst_margin));
            }
}

TEST(FillCoverage, DoubleLightsExactlyThePixelsInside) { coverage_everywhere<double>(false); }
TEST(FillCoverage, FixedLightsThePixelsInsideWithinItsTolerance) { coverage_everywhere<fixed>(false); }
TEST(FillCoverage, AntiAliasedEdgesKeepEveryCentreOnItsSide) {
    coverage_everywhere<double>(true);
    coverage_everywhere<fixed>(true);
}

// On the sphere a body that holds the antipode of O is drawn out to the antipode's circle: its
// picture is the ring between its outline and that circle, which bounds it too, cut to the
// shown disc (1 px inside the circle) as every outline is.
TEST(FillCoverage, ABodyHoldingTheAntipodeReachesTheShownDiscsEdge) {
    for (double r : {3.0, 3.1})
        for (const Shape& shape : {star_shape(), c_shape()}) {
            const Count d = check_coverage<double>(shape, {r, 40, 0}, 1, false);
            const Count f = check_coverage<fixed>(shape, {r, 40, 0}, 1, false);
            EXPECT_GT(d.inside, 1000) << shape.name << " r " << r;
            EXPECT_GT(f.lit, 1000) << shape.name << " r " << r;
        }
}

// ---- textures --------------------------------------------------------------------------------

using test::coordinate_image;
using test::texel_gap;

struct TexelCheck {
    long pixels = 0;
    int worst = 0;            // nearest: texels between the one drawn and the reference's
    double worst_offset = 0;  // bilinear: the reference's s, t against the blend's
};
// Every pixel drawn in the texture's colours holds the texel at its reference coordinates.
template <class T>
TexelCheck check_texels(world::World<T>& w, render::DrawScratch<T>& s, const Shape& shape, Place p, double K, bool bilinear,
                        double texture_scale = 1) {
    Render<T> out;
    fill_once(w, s, out, false);
    const Reference ref(K, shape, p, kW / 2.0 / static_cast<double>(w.R));
    TexelCheck c;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const render::Rgb v = out.at(x, y);
            if (v.b != 0x80) continue;  // not drawn
            Polar<double> q;
            if (!ref.point(x, y, q)) continue;
            double st, tt;
            ref.texcoord(q, 64, 64, texture_scale, st, tt);
            ++c.pixels;
            if (!bilinear) {
                const int gap = std::max(texel_gap(v.r / 4, static_cast<int>(std::floor(st))),
                                         texel_gap(v.g / 4, static_cast<int>(std::floor(tt))));
                c.worst = std::max(c.worst, gap);
                continue;
            }
            if (st < 1 || st > 63 || tt < 1 || tt > 63) continue;  // (the blend across the image's edge)
            c.worst_offset = std::max({c.worst_offset, std::abs(v.r / 4.0 + 0.5 - st), std::abs(v.g / 4.0 + 0.5 - tt)});
        }
    return c;
}

template <class T>
void texels_everywhere(bool bilinear) {
    for (const Shape& shape : {star_shape(), c_shape()})
        for (double K : kCurvatures)
            for (Place p : kPlaces) {
                world::World<T> w(scene_of(shape, p, K, coordinate_image(), bilinear));
                render::DrawScratch<T> s;
                s.prepare(w);
                const TexelCheck c = check_texels(w, s, shape, p, K, bilinear);
                EXPECT_GT(c.pixels, 300);
                // Nearest: the texel at the reference's coordinates, or (fixed point, and double
                // where the coordinate rounds across a texel's edge) the next one.
                if (!bilinear) {
                    EXPECT_LE(c.worst, 1) << shape.name << " K " << K << " r " << p.r;
                }
                // Bilinear: the blend's position within one texel (its 8-bit channels hold a
                // quarter texel).
                if (bilinear) {
                    EXPECT_LE(c.worst_offset, 1.0) << shape.name << " K " << K << " r " << p.r;
                }
            }
}

TEST(FillTexture, DoubleReadsTheTexelAtTheBodysLocalEquidistantCoordinates) { texels_everywhere<double>(false); }
TEST(FillTexture, FixedReadsTheSameTexelWithinOne) { texels_everywhere<fixed>(false); }
TEST(FillTexture, BilinearBlendsAtThoseCoordinates) {
    texels_everywhere<double>(true);
    texels_everywhere<fixed>(true);
}

// The image repeated eight times across a body (texture_scale 1/8: up to 7 texels a pixel), so
// that a texture coordinate interpolated along a run (render/fill_span.hpp) shows its error
// magnified: every pixel still reads the reference's texel or the next, at every K and place
// (toward the limit circle and the sphere's antipode, where the map bends hardest).
template <class T>
void dense_texels_everywhere() {
    for (const Shape& shape : {star_shape(), c_shape()})
        for (double K : kCurvatures)
            for (Place p : kPlaces) {
                world::World<T> w(scene_of(shape, p, K, coordinate_image(), false, 0.125));
                render::DrawScratch<T> s;
                s.prepare(w);
                const TexelCheck c = check_texels(w, s, shape, p, K, false, 0.125);
                EXPECT_GT(c.pixels, 300);
                EXPECT_LE(c.worst, 1) << shape.name << " K " << K << " r " << p.r;
            }
}
TEST(FillTexture, DenseTexturesReadWithinOneTexelWhereTheMapBends) {
    dense_texels_everywhere<double>();
    dense_texels_everywhere<fixed>();
}

// The texture stays on the body while K changes under it (the curvature keys: the same world,
// its polar numbers re-read in the new K, the drawing's caches kept), at every K on the way.
template <class T>
void texture_follows_k() {
    const Shape shape = star_shape();
    const Place p{1.5, 120, 35};
    world::World<T> w(scene_of(shape, p, -1, coordinate_image()));
    render::DrawScratch<T> s;
    s.prepare(w);
    for (double K : {-1.0, -0.5, 0.0, 0.5, 1.0, 0.3, -0.3}) {
        w.K = T(K);
        const TexelCheck c = check_texels(w, s, shape, p, K, false);
        EXPECT_GT(c.pixels, 300) << K;
        EXPECT_LE(c.worst, 1) << K;
    }
}
TEST(FillTexture, FollowsTheBodyThroughAChangeOfK) {
    texture_follows_k<double>();
    texture_follows_k<fixed>();
}

// ---- the geometry's parts --------------------------------------------------------------------

// unproject inverts each projection: a point projected and taken back is the same point.
TEST(FillGeometry, UnprojectInvertsEachProjection) {
    for (geo::Projection proj : geo::kProjections)
        for (double K : kCurvatures)
            for (double r : {0.0, 0.3, 1.2, 2.1})
                for (double th : {0.0, 1.0, 2.5, -2.0}) {
                    const Polar<double> q{r, th};
                    const geo::ProjectedPoint<double> pp = geo::project_polar(K, q, proj);
                    if (!pp.visible) continue;
                    const geo::Unprojected<double> u = geo::unproject(K, pp.X, pp.Y, proj);
                    ASSERT_TRUE(u.valid) << geo::projection_name(proj) << " K " << K << " r " << r;
                    const glm::dvec3 want = geo::ref::point(K, q);
                    EXPECT_NEAR(u.p.w, want.x, 1e-9) << geo::projection_name(proj) << " K " << K << " r " << r;
                    EXPECT_NEAR(u.p.x, want.y, 1e-9) << geo::projection_name(proj) << " K " << K << " r " << r;
                    EXPECT_NEAR(u.p.y, want.z, 1e-9) << geo::projection_name(proj) << " K " << K << " r " << r;
                }
}

// body_motion_inverse undoes body_motion.
TEST(FillGeometry, TheInverseMotionUndoesTheMotion) {
    for (double K : kCurvatures)
        for (Place p : kPlaces) {
            const Polar<double> c{p.r, deg(p.theta_deg)};
            const double f = deg(p.facing_deg);
            const geo::Motion<double> M = geo::body_motion(K, c, f), Mi = geo::body_motion_inverse(K, c, f);
            const geo::Vec3<double> v = geo::to_vec(K, Polar<double>{0.7, 1.1}), back = Mi(M(v));
            EXPECT_NEAR(back.w, v.w, 1e-12);
            EXPECT_NEAR(back.x, v.x, 1e-12);
            EXPECT_NEAR(back.y, v.y, 1e-12);
        }
}

// geo::point_in_polygon, the world frame's even-odd test, against the reference.
TEST(FillGeometry, PointInPolygonAgreesWithTheReference) {
    for (const Shape& shape : {star_shape(), c_shape(), bowtie_shape()})
        for (double K : kCurvatures)
            for (Place p : kPlaces) {
                const Reference ref(K, shape, p, 1);
                std::vector<geo::Vec3<double>> v;
                geo::Vec3<double> c;
                v.resize(shape.local.size());
                geo::body_vectors(K, ref.centre(), ref.facing(), shape.local.data(), v.size(), c, v.data());
                const geo::Motion<double> M = geo::body_motion(K, ref.centre(), ref.facing());
                const geo::Vec3<double> E{M.m[0][1], M.m[1][1], M.m[2][1]};
                int in = 0, out = 0;
                for (double dr : {-0.45, -0.25, -0.1, 0.0, 0.15, 0.3})
                    for (int k = 0; k < 48; ++k) {
                        const Polar<double> q = geo::ref::polar(
                            K, geo::ref::frame(K, ref.centre()) * geo::ref::Rot(k * kPi / 24) * geo::ref::Tr(K, 0.3 + dr) *
                                   glm::dvec3(1, 0, 0));
                        const bool want = ref.inside(q);
                        (want ? in : out) += 1;
                        // They may differ only on the outline (the margin, a slow search, only then).
                        if (geo::point_in_polygon(K, c, E, v.data(), v.size(), geo::to_vec(K, q)) != want) {
                            EXPECT_LT(ref.margin(q), 1e-9) << shape.name << " K " << K << " r " << p.r;
                        }
                    }
                EXPECT_GT(in, 40) << shape.name;
                EXPECT_GT(out, 40) << shape.name;
            }
}

}  // namespace
