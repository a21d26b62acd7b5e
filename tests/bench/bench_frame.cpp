// Frame cost of the kiosk scene: one world step plus drawing the whole frame into a RAM
// canvas, for the Pi's 800x480 RGB565 and a 1920x1080 XRGB8888 screen, fixed and double
// engines side by side in one run.
//     build/release/bench_frame
#include <benchmark/benchmark.h>

#include <vector>

#include "render/draw_world.hpp"

namespace {

using namespace noneuclid;

template <class T>
void frame(benchmark::State& st, int w, int h, render::PixelFormat f, bool aa) {
    world::Scene scene;
    world::builtin_scene("kiosk", {}, scene);
    world::World<T> wd(scene);
    render::DrawScratch<T> scratch;
    scratch.prepare(wd);
    std::vector<uint8_t> px(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * f.bytes_per_pixel());
    const render::Canvas c(px.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    render::DrawOptions o;
    o.antialias = aa;
    const double dt = 1.0 / 60;
    for (auto _ : st) {
        wd.step(dt);
        render::draw_world(c, wd, o, scratch);
        benchmark::DoNotOptimize(px.data());
    }
    st.counters["fps"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}

void fixed_800x480_rgb565(benchmark::State& s) { frame<fx::fixed>(s, 800, 480, render::PixelFormat::rgb565(), false); }
void double_800x480_rgb565(benchmark::State& s) { frame<double>(s, 800, 480, render::PixelFormat::rgb565(), false); }
void fixed_1920x1080_xrgb8888(benchmark::State& s) { frame<fx::fixed>(s, 1920, 1080, render::PixelFormat::xrgb8888(), false); }
void double_1920x1080_xrgb8888(benchmark::State& s) { frame<double>(s, 1920, 1080, render::PixelFormat::xrgb8888(), false); }
void fixed_1920x1080_xrgb8888_aa(benchmark::State& s) { frame<fx::fixed>(s, 1920, 1080, render::PixelFormat::xrgb8888(), true); }

}  // namespace

BENCHMARK(fixed_800x480_rgb565)->Unit(benchmark::kMicrosecond);
BENCHMARK(double_800x480_rgb565)->Unit(benchmark::kMicrosecond);
BENCHMARK(fixed_1920x1080_xrgb8888)->Unit(benchmark::kMicrosecond);
BENCHMARK(double_1920x1080_xrgb8888)->Unit(benchmark::kMicrosecond);
BENCHMARK(fixed_1920x1080_xrgb8888_aa)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
