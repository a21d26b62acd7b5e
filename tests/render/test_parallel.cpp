// The threaded frame (draw_world over a WorkerPool) writes the same pixels as one thread, bit
// for bit: every engine (fixed, float, double, the paper's), scenes with grids, many bodies and
// hidden points (gnomonic at K > 0), aliased and anti-aliased, thick lines, 1 to 4 threads,
// band edges anywhere (from one-row bands to the balanced default), frame after frame of a
// moving world, with the controls held (K changes every frame), with the backdrop left out,
// and on a canvas with fewer rows than threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "render/draw_world.hpp"
#include "render/parallel_frame.hpp"

namespace {

using namespace noneuclid;

struct Variant {
    bool backdrop = true;
    int32_t width = 256;   // line width, 1/256 px
    bool controls = false; // thrust, turn and curvature held
    std::vector<double> edges = {};  // one band per thread at these fixed rows (no balancing); empty: balanced
    uint32_t generation = 0;  // the scratch's frame count to start from
    int height = 207;         // the canvas's rows (odd: the bands are uneven)
};

template <class T, class E = geo::Exact<T>>
void threaded_equals_serial(const char* scene_name, double K, geo::Projection proj, bool aa, int threads,
                            render::PixelFormat f, Variant v = {}) {
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene(scene_name, {60, 7, 6}, scene));
    scene.curvature = K;
    world::World<T, E> w(scene);
    if (v.controls)
        for (world::Action a : {world::Action::thrust, world::Action::left, world::Action::curvature_down}) w.press(a);
    render::DrawScratch<T, E> serial;
    serial.prepare(w);
    render::WorkerPool pool(threads);
    render::ParallelScratch<T, E> par;
    par.prepare(w, pool);
    if (!v.edges.empty()) par.edge = v.edges, par.balance = false;
    par.generation = v.generation;
    const int W = 301, H = v.height;
    const std::size_t stride = static_cast<std::size_t>(W * f.bytes_per_pixel());
    std::vector<uint8_t> a(stride * H, 0x11), b(stride * H, 0x11);
    const render::Canvas ca(a.data(), W, H, static_cast<std::ptrdiff_t>(stride), f);
    const render::Canvas cb(b.data(), W, H, static_cast<std::ptrdiff_t>(stride), f);
    render::DrawOptions o;
    o.projection = proj;
    o.antialias = aa;
    o.line_width = v.width;
    for (int i = 0; i < 12; ++i) {
        w.step(0.05);
        render::draw_world(ca, w, o, serial, v.backdrop);
        render::draw_world(cb, w, o, par, pool, v.backdrop);
        ASSERT_EQ(a, b) << scene_name << " K " << K << " threads " << threads << " frame " << i;
    }
    // Not two blank pictures: the bodies and grids put pixels where the backdrop alone has none.
    std::vector<uint8_t> bare(stride * H, 0x11);
    const render::Canvas cbare(bare.data(), W, H, static_cast<std::ptrdiff_t>(stride), f);
    render::DrawOptions none = o;
    none.grids = none.bodies = false;
    render::draw_world(cbare, w, none, serial, v.backdrop);
    long drawn = 0;
    for (std::size_t i = 0; i < a.size(); ++i) drawn += a[i] != bare[i];
    EXPECT_GT(drawn, H >= 100 ? 200 : 0) << scene_name << " K " << K;  // (a few rows: a few pixels)
}

TEST(Parallel, SamePixelsAsOneThreadEveryEngine) {
    const render::PixelFormat fmts[] = {render::PixelFormat::rgb565(), render::PixelFormat::xrgb8888(),
                                        render::PixelFormat::rgb888()};
    int fi = 0;
    for (int threads : {1, 2, 3, 4})
        for (bool aa : {false, true}) {
            const render::PixelFormat f = fmts[fi++ % 3];
            threaded_equals_serial<fx::fixed>("kiosk", -0.5, geo::Projection::azimuthal_equidistant, aa, threads, f);
            threaded_equals_serial<fx::fixed>("stress", -1, geo::Projection::stereographic, aa, threads, f);
            threaded_equals_serial<fx::fixed>("kiosk", 0.9, geo::Projection::gnomonic, aa, threads, f);
            threaded_equals_serial<double>("stress", 0.7, geo::Projection::orthographic, aa, threads, f);
            threaded_equals_serial<double>("fig17", 0, geo::Projection::azimuthal_equidistant, aa, threads, f);
            threaded_equals_serial<float>("kiosk", 0.3, geo::Projection::lambert_equal_area, aa, threads, f);
            threaded_equals_serial<float>("stress", -0.2, geo::Projection::gnomonic, aa, threads, f);
            threaded_equals_serial<double, geo::Paper>("kiosk", 0.5, geo::Projection::azimuthal_equidistant, aa, threads, f);
            // Filled and textured bodies: their fills planned by each body's thread, drawn band by band.
            threaded_equals_serial<fx::fixed>("textured", -1, geo::Projection::azimuthal_equidistant, aa, threads, f);
            threaded_equals_serial<fx::fixed>("textured", 1, geo::Projection::azimuthal_equidistant, aa, threads, f);
            threaded_equals_serial<double>("textured", 0.5, geo::Projection::stereographic, aa, threads, f);
            threaded_equals_serial<float>("textured", -0.3, geo::Projection::gnomonic, aa, threads, f);
        }
}

TEST(Parallel, WithoutBackdropAndOptions) {
    threaded_equals_serial<fx::fixed>("kiosk", 0.2, geo::Projection::azimuthal_equidistant, false, 2,
                                      render::PixelFormat::rgb565(), {.backdrop = false});
    threaded_equals_serial<double>("stress", -0.4, geo::Projection::azimuthal_equidistant, true, 3,
                                   render::PixelFormat::xrgb8888(), {.backdrop = false});
}

// One band per thread with its edges anywhere (as balance_bands may put them): one-row bands,
// a thread with nearly all rows, uneven thirds.
TEST(Parallel, BandEdgesAnywhere) {
    const std::vector<std::vector<double>> two = {{0, 1, 207}, {0, 206, 207}, {0, 61.4, 207}, {0, 150.6, 207}};
    for (const auto& e : two)
        for (bool aa : {false, true}) {
            const render::PixelFormat f = aa ? render::PixelFormat::xrgb8888() : render::PixelFormat::rgb565();
            threaded_equals_serial<fx::fixed>("stress", -1, geo::Projection::azimuthal_equidistant, aa, 2, f, {.edges = e});
            threaded_equals_serial<double>("kiosk", 0.4, geo::Projection::stereographic, aa, 2, f, {.edges = e});
        }
    threaded_equals_serial<fx::fixed>("stress", -0.6, geo::Projection::azimuthal_equidistant, true, 3,
                                      render::PixelFormat::rgb565(), {.width = 700, .edges = {0, 1, 2, 207}});
    threaded_equals_serial<double>("stress", 0.2, geo::Projection::azimuthal_equidistant, false, 3,
                                   render::PixelFormat::rgb888(), {.edges = {0, 180, 199.5, 207}});
}

// Bands with their edges anywhere (one row, a few, about half, nearly all), thick and thin
// lines, aliased and anti-aliased: the bodies cross band edges everywhere.
TEST(Parallel, AnyBandEdgeAndLineWidth) {
    const render::PixelFormat fmts[] = {render::PixelFormat::rgb565(), render::PixelFormat::xrgb8888(),
                                        render::PixelFormat::rgb888()};
    const int32_t widths[] = {256, 700, 90};
    int fi = 0;
    for (int rows : {1, 9, 50, 200})
        for (bool aa : {false, true})
            for (int wi = 0; wi < 2; ++wi) {
                const render::PixelFormat f = fmts[fi++ % 3];
                const int32_t width = widths[(fi + wi) % 3];
                const int threads = 2 + fi % 2;
                std::vector<double> edges = {0, double(rows)};
                if (threads == 3) edges.push_back(std::min(206.0, 2.0 * rows + 0.4));
                edges.push_back(207);
                threaded_equals_serial<fx::fixed>("kiosk", -0.8, geo::Projection::azimuthal_equidistant, aa, threads, f,
                                                  {.width = width, .edges = edges});
                threaded_equals_serial<double>("stress", 0.4, geo::Projection::stereographic, aa, threads, f,
                                               {.width = width, .edges = edges});
            }
}

// The frame count wraps past 2^32 - 1 within the 12 frames: the flags are cleared and 0 is
// skipped, and the pixels stay those of one thread (a frame numbered 0 would take every
// cleared entry for written). The race the clearing prevents, a list entry unwritten for 2^32
// frames read before its thread rewrites it, cannot be brought about on demand.
TEST(Parallel, FrameCountWraps) {
    for (int threads : {2, 3}) {
        const Variant v{.generation = UINT32_MAX - 5};
        threaded_equals_serial<fx::fixed>("stress", -1, geo::Projection::azimuthal_equidistant, false, threads,
                                          render::PixelFormat::rgb565(), v);
    }
    render::WorkerPool pool(2);
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene("stress", {60, 7, 6}, scene));
    world::World<double> w(scene);
    render::ParallelScratch<double> par;
    par.prepare(w, pool);
    par.generation = UINT32_MAX - 1;
    EXPECT_EQ(par.next_generation(), UINT32_MAX);
    EXPECT_EQ(par.next_generation(), 1u);
    EXPECT_EQ(par.next_generation(), 2u);
}

// balance_bands, on made-up busy times: an edge moves towards the busier band by gain x the
// relative difference x the two bands' rows, stays when the times are equal, and never leaves a
// band without a row.
TEST(Parallel, BalanceBandsMovesEdgesTowardsTheBusierBand) {
    std::vector<double> edge = {0, 100, 200}, smoothed = {0, 0};
    const double busy[] = {3e-4, 1e-4};
    render::balance_bands(edge, busy, smoothed, 0.5, 0.75);
    EXPECT_DOUBLE_EQ(smoothed[0], 3e-4);  // the first frame is taken as it is
    EXPECT_DOUBLE_EQ(edge[1], 100 - 0.5 * (3e-4 - 1e-4) / (3e-4 + 1e-4) * 200);  // 50
    const double equal[] = {2e-4, 2e-4};
    render::balance_bands(edge, equal, smoothed, 0.5, 0.75);  // smoothed: 2.75e-4, 1.25e-4
    EXPECT_NEAR(edge[1], 50 - 0.5 * (1.5e-4 / 4e-4) * 200, 1e-9);
    std::vector<double> e3 = {0, 10, 20, 207}, s3 = {0, 0, 0};
    const double skewed[] = {1.0, 1e-9, 1.0};
    for (int i = 0; i < 200; ++i) {
        render::balance_bands(e3, skewed, s3);
        ASSERT_GE(e3[1], e3[0] + 1);
        ASSERT_GE(e3[2], e3[1] + 1);
        ASSERT_LE(e3[2], e3[3] - 1);
    }
    EXPECT_NEAR(e3[1], 1, 0.05);  // the busy first band shrank to its one row
    std::vector<double> flat = {0, 70, 207}, sf = {0, 0};
    const double same[] = {5e-5, 5e-5};
    render::balance_bands(flat, same, sf);
    EXPECT_DOUBLE_EQ(flat[1], 70);
}

// row_span (the rows a body's points span, for the bands) against its definition: the least
// and the greatest y over the points that are not breaks, {INT32_MAX, INT32_MIN} when there is
// none. Points anywhere in to_sub's range (+-2^30) and beyond, to the ends of int32 (but not
// INT32_MIN: that y is a break's), breaks anywhere among them, every length from 0 (the
// vectorised loop's remainders).
TEST(Parallel, RowSpanIsTheLeastAndGreatestYWithoutBreaks) {
    uint32_t x = 12345u;
    auto next = [&x] { return x ^= x << 13, x ^= x >> 17, x ^= x << 5; };
    std::vector<render::SubPoint> pts;
    int all_breaks = 0;
    for (int n = 0; n <= 40; ++n)
        for (int rep = 0; rep < 200; ++rep) {
            pts.resize(static_cast<std::size_t>(n));
            const uint32_t break_odds = next() % 4;  // none, 1 in 2, 1 in 8, all
            for (auto& p : pts) {
                const bool brk = break_odds == 3 || (break_odds == 1 && next() % 2 == 0) || (break_odds == 2 && next() % 8 == 0);
                const int32_t y = static_cast<int32_t>(next() % (2u << 30)) - (1 << 30);  // [-2^30, 2^30)
                const uint32_t u = next();
                const int32_t any = static_cast<int32_t>(u == 0x80000000u ? 0u : u);  // any int32 but INT32_MIN
                p = brk ? render::kBreak
                        : render::SubPoint{static_cast<int32_t>(next() % 1000), rep % 5 == 0 ? y / 4096 : (rep % 5 == 1 ? any : y)};
            }
            int32_t top = INT32_MAX, bottom = INT32_MIN;
            for (const auto& p : pts)
                if (!(p.x == render::kBreak.x && p.y == render::kBreak.y)) top = std::min(top, p.y), bottom = std::max(bottom, p.y);
            all_breaks += top == INT32_MAX;
            const render::RowSpan s = render::row_span(pts.data(), pts.size());
            ASSERT_EQ(s.top, top) << "n " << n << " rep " << rep;
            ASSERT_EQ(s.bottom, bottom) << "n " << n << " rep " << rep;
        }
    // The ends of the range too.
    const render::SubPoint ends[] = {{0, INT32_MIN + 1}, render::kBreak, {0, INT32_MAX}};
    const render::RowSpan e = render::row_span(ends, 3);
    EXPECT_EQ(e.top, INT32_MIN + 1);
    EXPECT_EQ(e.bottom, INT32_MAX);
    EXPECT_GT(all_breaks, 1000);  // the "no point" answer was checked, often
}

// With the controls held (thrust, turn, curvature: K and so every body's shape change every
// frame), every engine.
TEST(Parallel, ControlsHeldEveryEngine) {
    for (int threads : {1, 2, 3, 4})
        for (bool aa : {false, true}) {
            const render::PixelFormat f = aa ? render::PixelFormat::xrgb8888() : render::PixelFormat::rgb565();
            const Variant v{.controls = true};
            threaded_equals_serial<fx::fixed>("stress", -1, geo::Projection::azimuthal_equidistant, aa, threads, f, v);
            threaded_equals_serial<fx::fixed>("kiosk", 0.5, geo::Projection::gnomonic, aa, threads, f, v);
            threaded_equals_serial<double>("stress", 0.3, geo::Projection::azimuthal_equidistant, aa, threads, f, v);
            threaded_equals_serial<float>("kiosk", -0.3, geo::Projection::orthographic, aa, threads, f, v);
            threaded_equals_serial<double, geo::Paper>("kiosk", 0.6, geo::Projection::azimuthal_equidistant, aa, threads, f, v);
        }
}

// A canvas with fewer rows than threads (drawn on the calling thread alone), and one row per
// thread.
TEST(Parallel, CanvasWithFewRows) {
    for (int height : {1, 2, 3})
        for (int threads : {2, 3, 4})
            threaded_equals_serial<fx::fixed>("stress", -1, geo::Projection::azimuthal_equidistant, height % 2 == 0, threads,
                                              render::PixelFormat::rgb565(), {.height = height});
}

// The pool runs each job once per thread, every time, and can be used for many frames.
TEST(Parallel, PoolRunsEveryThreadEveryTime) {
    for (int n : {1, 2, 5}) {
        render::WorkerPool pool(n);
        EXPECT_EQ(pool.size(), n);
        std::vector<int> hits(static_cast<std::size_t>(n), 0);
        for (int r = 0; r < 500; ++r) {
            auto job = [&](int i) { ++hits[static_cast<std::size_t>(i)]; };
            pool.run(job);
        }
        for (int h : hits) EXPECT_EQ(h, 500);
    }
}

}  // namespace
