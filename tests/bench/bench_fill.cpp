// What a filled or textured body costs per pixel, beside a memset of as many pixels, side by
// side in one run (Google Benchmark):
//     build/release/bench_fill --benchmark_repetitions=3
// The built-in scene `textured` (five textured bodies about 60 px across on 800x480, and one
// filled; render/fill.hpp), after 30 steps, in each of:
//   filled     every body filled with a colour instead (the fill's runs and edge zones alone)
//   nearest    the textures as the scene has them, the nearest texel
//   bilinear   the same, four texels blended
//   memset     std::memset of as many pixels as the fills cover (the floor)
// each for the fixed and double engines, at 800x480 RGB565 (the Pi's display) and 1920x1080
// XRGB8888 (the bodies 2.25 times as wide). A fill is the whole of what draw_world does for
// the bodies' insides: the plan (polyline, zones) and the rows. A summary table (ns per
// covered pixel, the pixels counted once with colours, and the ratio to memset) follows.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "displays.hpp"
#include "render/draw_world.hpp"
#include "fastest.hpp"

namespace {

using namespace noneuclid;

std::map<std::string, double> g_ns;     // fastest ns per iteration, by benchmark name
std::map<std::string, double> g_pixels;  // pixels covered, by display and variant

template <class T>
struct Setup {
    world::Scene scene;
    world::World<T> wd;
    render::DrawScratch<T> scratch;
    std::vector<uint8_t> back;
    render::Canvas c;
    render::DrawOptions o;
    render::ScreenMap<T> m;
    std::size_t covered = 0;
    static world::Scene make(const std::string& variant) {
        world::Scene s;
        world::builtin_scene("textured", {}, s);
        for (world::SceneBody& b : s.bodies) {
            if (!b.texture) continue;
            if (variant == "filled") b.texture = nullptr, b.filled = true, b.fill = {200, 120, 60};
            b.texture_bilinear = variant == "bilinear";
        }
        return s;
    }
    Setup(const std::string& variant, int w, int h, render::PixelFormat f)
        : scene(make(variant)), wd(scene),
          back(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(f.bytes_per_pixel())),
          c(back.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f),
          m(render::ScreenMap<T>::of(c, wd.K, wd.R, o.projection)) {
        scratch.prepare(wd);
        for (int i = 0; i < 30; ++i) wd.step(1.0 / 60);
        render::draw_world(c, wd, o, scratch);
        std::fill(back.begin(), back.end(), 0);
        fills();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) covered += c.get_word(x, y) != 0;
    }
    // The fills alone, as draw_world draws them on one thread.
    void fills() {
        scratch.fill.begin_frame(c);
        for (std::size_t b = 0; b < wd.bodies.size(); ++b)
            if (render::body_shown(wd.bodies[b], o))
                if (const render::FillJob* j = scratch.fill.plan(wd, b, m, o, c.width(), c.height()))
                    render::fill_rows(c, *j, 0, c.height(), scratch.fill.work[0]);
    }
};

template <class T>
void run(benchmark::State& st, const std::string& key, const std::string& variant, int w, int h, render::PixelFormat f) {
    // memset covers as many pixels as the filled variant does (the same outlines).
    Setup<T> s(variant == "memset" ? "filled" : variant, w, h, f);
    g_pixels[key] = static_cast<double>(s.covered);
    const std::size_t bytes = s.covered * static_cast<std::size_t>(f.bytes_per_pixel());
    int v = 0;
    for (auto _ : st) {
        if (variant == "memset")
            std::memset(s.back.data(), ++v & 255, bytes);
        else
            s.fills();
        benchmark::DoNotOptimize(s.back.data());
        benchmark::ClobberMemory();
    }
    st.counters["pixels"] = static_cast<double>(s.covered);
}

const char* const kVariants[] = {"filled", "nearest", "bilinear", "memset"};

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    for (const BenchDisplay& cf : kBenchDisplays)
        for (const char* e : {"fixed", "double"})
            for (const char* variant : kVariants) {
                const std::string name = std::string(cf.name) + "/" + e + "/" + variant, v = variant;
                const int w = cf.w, h = cf.h;
                const render::PixelFormat f = cf.f;
                auto* b = std::string(e) == "fixed"
                              ? benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& s) { run<fx::fixed>(s, name, v, w, h, f); })
                              : benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& s) { run<double>(s, name, v, w, h, f); });
                b->Unit(benchmark::kMicrosecond);
            }
    FastestReporter rep([](const std::string& name, const benchmark::BenchmarkReporter::Run& r) {
        keep_fastest(g_ns, name, r.GetAdjustedCPUTime() * 1000);  // reported in us
    });
    benchmark::RunSpecifiedBenchmarks(&rep);
    std::printf("\nfills of the textured scene: ns per covered pixel (the ratio to a memset of as many pixels)\n\n");
    std::printf("| display | engine | pixels | filled | nearest | bilinear | memset |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|\n");
    for (const BenchDisplay& cf : kBenchDisplays)
        for (const char* e : {"fixed", "double"}) {
            const std::string at = std::string(cf.name) + "/" + e + "/";
            auto per_pixel = [&](const char* v) {
                const auto t = g_ns.find(at + v);
                const auto p = g_pixels.find(at + "memset");  // the filled outlines' pixels
                return t == g_ns.end() || p == g_pixels.end() || p->second <= 0 ? 0.0 : t->second / p->second;
            };
            const double floor = per_pixel("memset");
            if (floor <= 0) continue;
            std::printf("| %s | %s | %.0f |", cf.name, e, g_pixels[at + "memset"]);
            for (const char* v : {"filled", "nearest", "bilinear"}) std::printf(" %.3f (%.0f×) |", per_pixel(v), per_pixel(v) / floor);
            std::printf(" %.4f |\n", floor);
        }
    return 0;
}
