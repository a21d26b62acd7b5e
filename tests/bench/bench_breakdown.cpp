// Where a kiosk frame goes, stage by stage, side by side in one run (Google Benchmark):
//     build/release/bench_breakdown
// For 800x480 RGB565 (the Pi's display) and 1920x1080 XRGB8888, fixed and double engines:
//   step       the physics (World::step)
//   backdrop   background and shaded outside of the limit circle, as spans (draw_backdrop)
//   backdrop_pixelwise  the same pixels by Canvas::clear then shade_outside_circle, pixel
//              by pixel (for comparison)
//   geometry   every body's vertices, tessellated edges, projection, screen points
//   raster     the bodies' lines from those points (computed once before timing)
//   copy       render::copy_canvas, back buffer to a second ("framebuffer") buffer
//   memcpy     std::memcpy of the same bytes: the floor for the copy
//   frame      step + draw_world + copy_canvas, what the kiosk does per frame (HUD aside)
// A summary table (us per stage, share of the frame) follows.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "displays.hpp"
#include "render/blit.hpp"
#include "render/draw_world.hpp"
#include "fastest.hpp"

namespace {

using namespace noneuclid;

std::map<std::string, double> g_us;

template <class T>
struct Setup {
    world::Scene scene;
    world::World<T> wd;
    render::DrawScratch<T> scratch;
    std::vector<uint8_t> back, front;
    render::Canvas c, fb;
    render::DrawOptions o;
    render::ScreenMap<T> m;
    std::vector<render::SubPoint> pts;
    std::vector<std::size_t> counts;
    static world::Scene kiosk() {
        world::Scene s;
        world::builtin_scene("kiosk", {}, s);
        return s;
    }
    Setup(int w, int h, render::PixelFormat f)
        : scene(kiosk()), wd(scene),
          back(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(f.bytes_per_pixel())),
          front(back.size()),
          c(back.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f),
          fb(front.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f),
          m(render::ScreenMap<T>::of(c, wd.K, wd.R, o.projection)) {
        scratch.prepare(wd);
        for (int i = 0; i < 30; ++i) wd.step(1.0 / 60);
        render::draw_world(c, wd, o, scratch);
        for (std::size_t i = 0; i < wd.bodies.size(); ++i) {
            const auto& b = wd.bodies[i];
            std::vector<render::SubPoint> p(render::body_point_capacity(wd, b));
            const std::size_t k =
                render::body_screen_points(wd, b, scratch.shapes[i], m, o, scratch.vertices.data(), scratch.vectors.data(), p.data());
            pts.insert(pts.end(), p.begin(), p.begin() + static_cast<std::ptrdiff_t>(k));
            counts.push_back(k);
        }
    }
};

template <class T>
void stage(benchmark::State& st, const std::string& which, int w, int h, render::PixelFormat f) {
    Setup<T> s(w, h, f);
    const double dt = 1.0 / 60;
    for (auto _ : st) {
        if (which == "step") s.wd.step(dt);
        else if (which == "backdrop") render::draw_backdrop(s.c, s.m, s.o);
        else if (which == "backdrop_pixelwise") {
            s.c.clear(s.o.background);
            render::shade_outside_circle(s.c, static_cast<double>(s.m.cx), static_cast<double>(s.m.cy),
                                         static_cast<double>(s.m.scale) * static_cast<double>(s.wd.R), s.o.outside);
        } else if (which == "geometry") {
            std::size_t k = 0;
            for (std::size_t i = 0; i < s.wd.bodies.size(); ++i)
                k += render::body_screen_points(s.wd, s.wd.bodies[i], s.scratch.shapes[i], s.m, s.o, s.scratch.vertices.data(),
                                                s.scratch.vectors.data(), s.scratch.points.data());
            benchmark::DoNotOptimize(k);
        } else if (which == "raster") {
            std::size_t at = 0;
            for (std::size_t k = 0; k < s.wd.bodies.size(); ++k) {
                render::draw_screen_points(s.c, s.pts.data() + at, s.counts[k], render::body_color(s.wd.bodies[k], s.o), {});
                at += s.counts[k];
            }
        } else if (which == "copy") render::copy_canvas(s.c, s.fb);
        else if (which == "memcpy") std::memcpy(s.front.data(), s.back.data(), s.back.size());
        else if (which == "frame") {
            s.wd.step(dt);
            render::draw_world(s.c, s.wd, s.o, s.scratch);
            render::copy_canvas(s.c, s.fb);
        }
        benchmark::DoNotOptimize(s.back.data());
        benchmark::DoNotOptimize(s.front.data());
        benchmark::ClobberMemory();
    }
}

const char* const kStages[] = {"step", "backdrop", "backdrop_pixelwise", "geometry", "raster", "copy", "memcpy", "frame"};

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    for (const BenchDisplay& cf : kBenchDisplays)
        for (const char* e : {"fixed", "double"})
            for (const char* sname : kStages) {
                const std::string name = std::string(cf.name) + "/" + e + "/" + sname;
                const std::string which = sname;
                const int w = cf.w, h = cf.h;
                const render::PixelFormat f = cf.f;
                auto* b = std::string(e) == "fixed"
                              ? benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& s) { stage<fx::fixed>(s, which, w, h, f); })
                              : benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& s) { stage<double>(s, which, w, h, f); });
                b->Unit(benchmark::kMicrosecond);
            }
    FastestReporter rep([](const std::string& name, const benchmark::BenchmarkReporter::Run& r) {
        keep_fastest(g_us, name, r.GetAdjustedCPUTime());
    });
    benchmark::RunSpecifiedBenchmarks(&rep);
    std::printf("\nkiosk frame by stage, us of CPU time (share of the frame)\n\n");
    std::printf("| display | engine | step | backdrop | geometry | raster | copy | sum | frame | memcpy | copy/memcpy | backdrop pixelwise |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const BenchDisplay& cf : kBenchDisplays)
        for (const char* e : {"fixed", "double"}) {
            auto g = [&](const char* st) {
                auto it = g_us.find(std::string(cf.name) + "/" + e + "/" + st);
                return it == g_us.end() ? 0.0 : it->second;
            };
            const double fr = g("frame");
            if (fr <= 0) continue;
            const double sum = g("step") + g("backdrop") + g("geometry") + g("raster") + g("copy");
            auto pc = [&](double v) { return 100 * v / fr; };
            std::printf("| %s | %s | %.1f (%.0f%%) | %.1f (%.0f%%) | %.1f (%.0f%%) | %.1f (%.0f%%) | %.1f (%.0f%%) | %.1f | %.1f | %.1f | %.2f | %.1f |\n",
                        cf.name, e, g("step"), pc(g("step")), g("backdrop"), pc(g("backdrop")), g("geometry"), pc(g("geometry")),
                        g("raster"), pc(g("raster")), g("copy"), pc(g("copy")), sum, fr, g("memcpy"),
                        g("memcpy") > 0 ? g("copy") / g("memcpy") : 0.0, g("backdrop_pixelwise"));
        }
    return 0;
}
