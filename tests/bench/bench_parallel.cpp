// The threaded frame against one thread, side by side in one run (Google Benchmark):
//     build/release/bench_parallel
// World::step + draw_world on one thread (DrawScratch) against World::step + draw_world over a
// WorkerPool of 1, 2 and 4 threads (started once, before timing: the bodies' geometry and the
// raster bands on the pool), for stress (200 bodies x 8 vertices x level 8, K = -1) and kiosk,
// at 800x480 RGB565 and 1920x1080 XRGB8888, fixed and double engines. The world and the pixels
// are the same in every case, bit for bit (tests/render/test_parallel.cpp).
// Wall-clock time (UseRealTime): the threads' CPU time is not the caller's. The summary also
// shows how the work was split: the calling thread's CPU time (Google Benchmark's CPU column)
// and the whole process's (std::clock, every thread): on a machine whose other core is busy
// with someone else's work the wall clock cannot drop, but the split shows what two free cores
// would give: serial / max(caller's CPU, the other threads' CPU).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <map>
#include <string>
#include <vector>

#include "displays.hpp"
#include "render/draw_world.hpp"
#include "render/parallel_frame.hpp"
#include "fastest.hpp"

namespace {

using namespace noneuclid;

std::map<std::string, double> g_us, g_cpu, g_proc;

template <class T>
void frame(benchmark::State& st, const char* scene_name, int w, int h, render::PixelFormat f, int threads) {
    world::Scene scene;
    world::builtin_scene(scene_name, {}, scene);
    world::World<T> wd(scene);
    render::DrawScratch<T> serial;
    serial.prepare(wd);
    render::WorkerPool pool(threads > 0 ? threads : 1);
    render::ParallelScratch<T> par;
    par.prepare(wd, pool);
    std::vector<uint8_t> px(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(f.bytes_per_pixel()));
    const render::Canvas c(px.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    const render::DrawOptions o;
    const double dt = 1.0 / 60;
    const std::clock_t c0 = std::clock();
    for (auto _ : st) {
        wd.step(dt);
        if (threads == 0)
            render::draw_world(c, wd, o, serial);
        else
            render::draw_world(c, wd, o, par, pool);
        benchmark::DoNotOptimize(px.data());
        benchmark::ClobberMemory();
    }
    const double process_us = 1e6 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    st.counters["process_cpu_us"] = process_us / static_cast<double>(st.iterations());
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    const int thread_counts[] = {0, 1, 2, 4};  // 0: the single-thread overload
    for (const char* sc : {"stress", "kiosk"})
        for (const BenchDisplay& cf : kBenchDisplays)
            for (const char* e : {"fixed", "double"})
                for (int t : thread_counts) {
                    const std::string name = std::string(sc) + "/" + cf.name + "/" + e + "/" + (t == 0 ? "serial" : "threads" + std::to_string(t));
                    const int w = cf.w, h = cf.h;
                    const render::PixelFormat f = cf.f;
                    auto* b = std::string(e) == "fixed"
                                  ? benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& s) { frame<fx::fixed>(s, sc, w, h, f, t); })
                                  : benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& s) { frame<double>(s, sc, w, h, f, t); });
                    b->Unit(benchmark::kMicrosecond)->UseRealTime();
                }
    FastestReporter rep([](const std::string& name, const benchmark::BenchmarkReporter::Run& r) {
        if (!keep_fastest(g_us, name, r.GetAdjustedRealTime())) return;
        g_cpu[name] = r.GetAdjustedCPUTime();
        auto pc = r.counters.find("process_cpu_us");
        g_proc[name] = pc == r.counters.end() ? 0.0 : pc->second.value;
    });
    benchmark::RunSpecifiedBenchmarks(&rep);
    std::printf("\nframe (step + draw_world), us wall clock; speedup = serial / threaded (fastest repetition)\n");
    std::printf("split: calling thread's CPU us / every thread's CPU us per frame with 2 threads; 2 free cores = serial / "
                "max(caller, others)\n\n");
    std::printf("| scene | display | engine | serial | pool 1 | pool 2 | pool 4 | speedup 2 | speedup 4 | split 2 | 2 free cores |\n"
                "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const char* sc : {"stress", "kiosk"})
        for (const BenchDisplay& cf : kBenchDisplays)
            for (const char* e : {"fixed", "double"}) {
                const std::string base = std::string(sc) + "/" + cf.name + "/" + e + "/";
                auto g = [&](const char* t) {
                    auto it = g_us.find(base + t);
                    return it == g_us.end() ? 0.0 : it->second;
                };
                const double s0 = g("serial");
                if (s0 <= 0) continue;
                const double caller = g_cpu[base + "threads2"], all = g_proc[base + "threads2"];
                const double crit = std::max(caller, all - caller);
                std::printf("| %s | %s | %s | %.0f | %.0f | %.0f | %.0f | %.2f | %.2f | %.0f / %.0f | %.2f |\n", sc, cf.name, e, s0,
                            g("threads1"), g("threads2"), g("threads4"), g("threads2") > 0 ? s0 / g("threads2") : 0.0,
                            g("threads4") > 0 ? s0 / g("threads4") : 0.0, caller, all, crit > 0 ? s0 / crit : 0.0);
            }
    return 0;
}
