// The threaded frame against one thread, interleaved in one process, to take a shared host's
// noise out of the comparison (docs/performance.md):
//     build/release/parallel_ab [frames per variant, default 3000]
// For stress and kiosk at 800x480 RGB565 and 1920x1080 XRGB8888, fixed and double: chunks of 50
// frames in turn of (a) World::step + draw_world on one thread, (b) World::step + draw_world on
// a pool of 2 with the band edges balanced (the default), (c) the same with equal bands (balance
// off), (d) the host's ceiling: the same pool running two whole one-thread frames at once, each
// on a world and canvas of its own (nothing shared), and (e) World::step + draw_world on a pool
// of 1 (the threaded frame's code on one thread, one band), each variant on its own copies. A
// burst of noise from the host lands on all five alike. Prints each variant's median and 10th
// percentile frame in us, the speedups of the medians, the ceiling (2 x (a) / (d): what two
// cores give this frame's work with no sharing at all, at the time of the run) and where the
// balance left the edge between the two bands; then a second table: the phases of (e) and of
// (b)'s two threads (ParallelScratch::busy: geometry, raster with the backdrop, waits for the
// other thread's bodies), medians over the frames.
//
// The ceiling is there because a virtual machine's second core is not always a whole core:
// two independent frames at once can each take much longer than one frame alone, and how much
// changes within minutes.
//
// The last column is the cores' round trip: the pool's two threads hand one cache line back and
// forth (an atomic counter each increments in turn) and the time per round trip is taken, once
// between each round of chunks; its median. It is what one line written by one core and then
// read by the other costs at the time of the run, which on a shared host changes several-fold
// within minutes. The threaded frame shares lines between the cores (each band reads the
// bodies that cross it from the other core; the bodies of both threads lie side by side in one
// world), the ceiling's two frames do not: with a slow round trip the geometry phase costs more
// on two threads and the speedup drops while the ceiling stays.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "render/draw_world.hpp"
#include "render/parallel_frame.hpp"

namespace {

using namespace noneuclid;
using clk = std::chrono::steady_clock;

double quantile(std::vector<double> x, double p) {
    std::sort(x.begin(), x.end());
    return x[static_cast<std::size_t>(p * static_cast<double>(x.size() - 1))];
}

std::vector<std::string> phase_rows;  // the second table

// The time, in ns, of a cache line's round trip between the pool's threads 0 and 1, averaged
// over 4000 of them: each thread waits for the counter to reach its turn and increments it.
// (Spins without yielding: both threads are running, and each turn is a few hundred ns.)
double round_trip_ns(render::WorkerPool& pool) {
    constexpr int kTrips = 4000;
    struct alignas(64) Line {
        std::atomic<int> turn{0};
    } line;
    double ns = 0;
    auto job = [&](int t) {
        if (t > 1) return;
        const clk::time_point start = clk::now();
        for (int k = t; k < 2 * kTrips; k += 2) {
            while (line.turn.load(std::memory_order_acquire) != k) {
            }
            line.turn.store(k + 1, std::memory_order_release);
        }
        if (t == 0) ns = std::chrono::duration<double, std::nano>(clk::now() - start).count() / kTrips;
    };
    pool.run(job);
    return ns;
}

template <class T>
void compare(const char* scene_name, int w, int h, render::PixelFormat f, int frames) {
    world::Scene scene;
    world::builtin_scene(scene_name, {}, scene);
    world::World<T> w0(scene), w1(scene), w2(scene), w3(scene), w4(scene), w5(scene);
    render::DrawScratch<T> serial, alone[2];
    serial.prepare(w0);
    render::WorkerPool pool(2);
    {
        // Each of the two frames' scratch is allocated by the thread that uses it (glibc gives
        // each thread its own heap): allocated one after the other by one thread, the first
        // scratch's 3-vectors and the second's points could share a cache line, which both
        // cores would write for every body, and the ceiling would come out low.
        world::World<T>* const own[2] = {&w3, &w4};
        auto prepare_own = [&](int t) { alone[t].prepare(*own[t]); };
        pool.run(prepare_own);
    }
    render::ParallelScratch<T> balanced, equal;
    balanced.prepare(w1, pool);
    equal.prepare(w2, pool);
    equal.balance = false;
    render::WorkerPool pool1(1);
    render::ParallelScratch<T> one;
    one.prepare(w5, pool1);
    std::vector<uint8_t> px(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(f.bytes_per_pixel()));
    const render::Canvas c(px.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    std::vector<uint8_t> px3(px.size()), px4(px.size());
    const render::Canvas c3(px3.data(), w, h, c.stride(), f), c4(px4.data(), w, h, c.stride(), f);
    const render::DrawOptions o;
    const double dt = 1.0 / 60;
    world::World<T>* const own_world[2] = {&w3, &w4};
    const render::Canvas* const own_canvas[2] = {&c3, &c4};
    auto two_alone = [&](int t) {
        own_world[t]->step(dt);
        render::draw_world(*own_canvas[t], *own_world[t], o, alone[t]);
    };
    std::vector<double> ts, tb, te, ti, t1, rt;
    // Phases in us: (e)'s geometry and raster, (b)'s per thread geometry, raster and waits.
    std::vector<double> g1, r1, g[2], r[2], wt[2];
    auto us = [](double seconds) { return seconds * 1e6; };
    auto timed = [](std::vector<double>& out, auto&& frame) {
        const clk::time_point a = clk::now();
        frame();
        out.push_back(std::chrono::duration<double, std::micro>(clk::now() - a).count());
    };
    constexpr int kChunk = 50;
    for (int done = 0; done < frames; done += kChunk, rt.push_back(round_trip_ns(pool)))
        for (int v = 0; v < 5; ++v)
            for (int i = 0; i < kChunk; ++i) {
                if (v == 0) timed(ts, [&] { w0.step(dt), render::draw_world(c, w0, o, serial); });
                if (v == 1) {
                    timed(tb, [&] { w1.step(dt), render::draw_world(c, w1, o, balanced, pool); });
                    for (int t = 0; t < 2; ++t) {
                        const auto& b = balanced.busy[static_cast<std::size_t>(t)];
                        g[t].push_back(us(b.geometry)), r[t].push_back(us(b.seconds - b.geometry)), wt[t].push_back(us(b.waited));
                    }
                }
                if (v == 2) timed(te, [&] { w2.step(dt), render::draw_world(c, w2, o, equal, pool); });
                if (v == 3) timed(ti, [&] { pool.run(two_alone); });
                if (v == 4) {
                    timed(t1, [&] { w5.step(dt), render::draw_world(c, w5, o, one, pool1); });
                    g1.push_back(us(one.busy[0].geometry)), r1.push_back(us(one.busy[0].seconds - one.busy[0].geometry));
                }
            }
    const double s = quantile(ts, 0.5), b = quantile(tb, 0.5), e = quantile(te, 0.5), i = quantile(ti, 0.5);
    std::printf("| %s | %dx%d | %s | %.0f (%.0f) | %.0f (%.0f) | %.2f | %.0f (%.0f) | %.2f | %.0f (%.0f) | %.2f | %.1f of %d | %.0f |\n",
                scene_name, w, h, sizeof(T) == sizeof(double) ? "double" : "fixed", s, quantile(ts, 0.1), b, quantile(tb, 0.1),
                s / b, e, quantile(te, 0.1), s / e, i, quantile(ti, 0.1), 2 * s / i,
                balanced.edge.size() > 1 ? balanced.edge[1] : 0.0, h, quantile(rt, 0.5));
    char row[400];
    auto m = [](const std::vector<double>& x) { return quantile(x, 0.5); };
    std::snprintf(row, sizeof row, "| %s | %dx%d | %s | %.0f | %.1f | %.1f | %.1f / %.1f | %.1f / %.1f | %.1f / %.1f |\n",
                  scene_name, w, h, sizeof(T) == sizeof(double) ? "double" : "fixed", m(t1), m(g1), m(r1), m(g[0]), m(g[1]),
                  m(r[0]), m(r[1]), m(wt[0]), m(wt[1]));
    phase_rows.push_back(row);
}

}  // namespace

int main(int argc, char** argv) {
    const int frames = argc > 1 ? std::atoi(argv[1]) : 3000;
    if (frames < 50) {
        std::fprintf(stderr, "parallel_ab: frames per variant must be 50 or more (got %s)\n", argc > 1 ? argv[1] : "");
        return 2;
    }
    std::printf("frame in us: median (10th percentile) of %d frames per variant, interleaved in chunks of 50\n\n", frames);
    std::printf("| scene | display | engine | 1 thread | 2 threads, balanced | speedup | 2 threads, equal bands | speedup | "
                "two 1-thread frames at once | ceiling | edge after | cores' round trip, ns |\n"
                "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const char* sc : {"stress", "kiosk"}) {
        compare<fx::fixed>(sc, 800, 480, render::PixelFormat::rgb565(), frames);
        compare<double>(sc, 800, 480, render::PixelFormat::rgb565(), frames);
        compare<fx::fixed>(sc, 1920, 1080, render::PixelFormat::xrgb8888(), frames);
        compare<double>(sc, 1920, 1080, render::PixelFormat::xrgb8888(), frames);
    }
    std::printf("\nphases in us, medians: a pool of 1 (its frame, geometry, raster) and the two threads of a pool of 2 "
                "(balanced; thread 0 / thread 1)\n\n| scene | display | engine | pool of 1 | geometry | raster | "
                "geometry, 2 threads | raster, 2 threads | waited |\n|---|---|---|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& row : phase_rows) std::fputs(row.c_str(), stdout);
    return 0;
}
