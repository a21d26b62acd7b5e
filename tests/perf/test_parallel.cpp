// The threaded frame (draw_world over a WorkerPool) writes the same pixels as one thread, bit
// for bit: every engine (fixed, float, double, the paper's), scenes with grids, many bodies and
// hidden points (gnomonic at K > 0), aliased and anti-aliased, 1 to 4 threads, frame after
// frame of a moving world, and with the backdrop left out.
#include <gtest/gtest.h>

#include <vector>

#include "render/draw_world.hpp"

namespace {

using namespace noneuclid;

template <class T, bool Paper = false>
void threaded_equals_serial(const char* scene_name, double K, geo::Projection proj, bool aa, int threads,
                            render::PixelFormat f, bool backdrop = true) {
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene(scene_name, {60, 7, 6}, scene));
    scene.curvature = K;
    world::World<T, Paper> w(scene);
    render::DrawScratch<T> serial;
    serial.prepare(w);
    render::WorkerPool pool(threads);
    render::ParallelScratch<T> par;
    par.prepare(w, pool);
    const int W = 301, H = 207;  // odd sizes: the last band is partial
    const std::size_t stride = static_cast<std::size_t>(W * f.bytes_per_pixel());
    std::vector<uint8_t> a(stride * H, 0x11), b(stride * H, 0x11);
    const render::Canvas ca(a.data(), W, H, static_cast<std::ptrdiff_t>(stride), f);
    const render::Canvas cb(b.data(), W, H, static_cast<std::ptrdiff_t>(stride), f);
    render::DrawOptions o;
    o.projection = proj;
    o.antialias = aa;
    for (int i = 0; i < 12; ++i) {
        w.step(T(0.05));
        render::draw_world(ca, w, o, serial, backdrop);
        render::draw_world(cb, w, o, par, pool, backdrop);
        ASSERT_EQ(a, b) << scene_name << " K " << K << " threads " << threads << " frame " << i;
    }
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
            threaded_equals_serial<double, true>("kiosk", 0.5, geo::Projection::azimuthal_equidistant, aa, threads, f);
        }
}

TEST(Parallel, WithoutBackdropAndOptions) {
    threaded_equals_serial<fx::fixed>("kiosk", 0.2, geo::Projection::azimuthal_equidistant, false, 2,
                                      render::PixelFormat::rgb565(), false);
    threaded_equals_serial<double>("stress", -0.4, geo::Projection::azimuthal_equidistant, true, 3,
                                   render::PixelFormat::xrgb8888(), false);
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
