// Drawing a world over a WorkerPool: the same frame as draw_world(canvas, world, options,
// DrawScratch&) (render/draw_world.hpp), pixel for pixel, on pool.size() threads, in one
// pool.run, with one band of rows per thread (thread t draws band t):
//  1. geometry (detail::geometry_of_thread): each thread computes the screen points of its home
//     bodies (ParallelScratch::home) and the rows they span, and enters each body in its list
//     for every band it reaches (BandEntry). An entry's flag says it is written;
//  2. raster (detail::raster_band, parallel_frame.cpp): each thread draws its band whole: its
//     backdrop, then every body's fill (render/fill.hpp) and lines clipped to the band (RowRange: exactly the pixels the
//     whole line has there), in the world's order (the threads' lists for the band merged),
//     waiting (yielding) for what another thread has not written yet.
// Bands are disjoint, so no two threads write one pixel, and each pixel gets the same writes in
// the same order as on one thread. After the frame the bands' edges move to even out the
// threads' times (balance_bands); the pixels do not depend on where the edges are.
//
// Memory: a ParallelScratch sized once for the world and the pool (prepare) holds every buffer;
// drawing a frame allocates nothing.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/geometry.hpp"
#include "render/backdrop.hpp"
#include "render/body_points.hpp"
#include "render/canvas.hpp"
#include "render/draw_options.hpp"
#include "render/fill.hpp"
#include "render/raster.hpp"
#include "render/screen_points.hpp"
#include "render/worker_pool.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

// The most threads a frame is split over (a body's home thread is a byte). A larger pool, or a
// canvas with fewer rows than threads, is drawn on the calling thread alone.
inline constexpr int kMaxBandThreads = 255;

// What a thread's geometry leaves for one band's raster, per body of its own that reaches the
// band, in a list only that thread writes (ParallelScratchBase::lists), in the world's order;
// an entry with idx kEnd closes the list. A band's raster merges the threads' lists for it by
// idx, so it reads nothing of the bodies that do not reach it, and nothing of the world: the
// colour is in the entry.
struct BandEntry {
    static constexpr uint32_t kEnd = UINT32_MAX;
    int32_t top = 0, bottom = 0;       // the points' smallest and largest y, 1/256 px
    uint32_t count = 0;                // entries at points
    uint32_t idx = kEnd;               // the body's index in World::bodies
    const SubPoint* points = nullptr;  // in the arena of the thread that did the body
    Rgb color{};
    const FillJob* fill = nullptr;   // the body's fill, drawn first (render/fill.hpp)
    std::atomic<uint32_t> ready{0};  // the frame generation this entry was written in
};

// The part of ParallelScratch that does not depend on the scalar (parallel_frame.cpp).
struct ParallelScratchBase {
    // Each thread writes the points of the bodies it does one after the other into an arena of
    // its own (thread t's from t * stride_points), so that a core's writes form one stream in
    // memory that no other core writes.
    std::vector<SubPoint> points;
    std::size_t stride_points = 1;
    std::size_t bodies = 0;
    uint32_t generation = 0;  // the frame count, for the lists' ready flags
    // Thread t's band is rows [edge[t], edge[t + 1]) (rounded), moved after each frame towards
    // equal busy time (balance_bands) unless balance is false. Empty: equal bands (set again
    // whenever the canvas height or the pool changes).
    std::vector<double> edge;
    bool balance = true;
    struct alignas(64) Busy {
        double seconds = 0;   // the thread's time in the last frame, waits for other threads left out
        double geometry = 0;  // of which its geometry phase, for benchmarks
        double waited = 0;    // and the time it waited for another thread's bodies
    };
    std::unique_ptr<Busy[]> busy;
    std::vector<double> smoothed;  // busy time, smoothed over frames
    // Each body's geometry is done by the thread whose band held the middle of its points last
    // frame (its "home"), so that the raster mostly reads points its own core wrote. home[g & 1]
    // is read in frame g, home[(g + 1) & 1] written for the next.
    std::vector<uint8_t> home[2];
    // Thread u's list for band k is the bodies' + 1 entries from
    // lists[(u * threads + k) * stride_list]; between two lists lie at least 64 bytes, so no
    // cache line holds two threads' entries.
    std::unique_ptr<BandEntry[]> lists;
    std::size_t stride_list = 1, list_entries = 0;
    BandEntry* list(int thread, int band, int threads) const {
        return lists.get() + (static_cast<std::size_t>(thread) * static_cast<std::size_t>(threads) +
                              static_cast<std::size_t>(band)) * stride_list;
    }

    // The next frame's generation, never 0. When the count wraps past 2^32 - 1, every ready
    // flag is cleared first: a list entry that went unwritten for 2^32 frames (a list shorter
    // all that time) would otherwise carry the new frame's number before its thread wrote it.
    uint32_t next_generation();
    // Room a body of n points takes in an arena: whole cache lines (8 points), so each body's
    // points start a line.
    static std::size_t arena_step(std::size_t n) { return (n + 7) / 8 * 8; }

protected:
    // Sizes everything above for `bodies` bodies whose points take `arena` entries in all (each
    // body's arena_step), on `threads` threads.
    void prepare_bands(std::size_t bodies, std::size_t arena, int threads);
};

// Buffers for draw_world over a WorkerPool: every body's points at once, each thread's band
// lists, vertices and 3-vectors, every body's cache of its engine E. Sized by prepare, for this
// world and this pool: prepare again for another.
template <class T, class E = geo::Exact<T>>
struct ParallelScratch : ParallelScratchBase {
    // Each thread's vertices and 3-vectors: thread t's start at t * stride, slices whole cache
    // lines apart (no line written by two threads).
    std::vector<geo::Polar<T>> vertices;
    std::vector<geo::Vec3<T>> vectors;
    std::size_t stride_v = 1, stride_vec = 1;
    std::vector<typename E::Cache> shapes;  // world.bodies[i]'s is shapes[i], refreshed by the thread that does it
    FillScratch<T> fill;                // each body's fill planned by the thread that does it; a RowWork per thread
    geo::DetailScale detail;            // the view's scale for lines simplified to it (geometry/detail.hpp)
    bool any_detail = false;

    template <class W>
    void prepare(const W& world, const WorkerPool& pool) {
        std::size_t most_v = 1, arena = 0;
        for (const auto& b : world.bodies) {
            arena += arena_step(body_point_capacity(world, b));  // one thread may do every body
            most_v = std::max(most_v, b.local.size());
        }
        prepare_bands(world.bodies.size(), arena, pool.size());
        // most_v entries rounded up to whole lines, plus a line: the vector's start need not be
        // on a line boundary.
        auto stride = [most_v](std::size_t size) { return ((most_v * size + 63) / 64 + 1) * 64 / size + 1; };
        stride_v = stride(sizeof(geo::Polar<T>)), stride_vec = stride(sizeof(geo::Vec3<T>));
        vertices.resize(stride_v * static_cast<std::size_t>(pool.size()));
        vectors.resize(stride_vec * static_cast<std::size_t>(pool.size()));
        make_shape_caches(world, shapes);
        any_detail = render::any_detail(shapes);
        fill.prepare(world, pool.size());
    }
};

// Moves the band edges after a frame so that the threads' busy times even out: each inner edge
// goes towards the busier of its two bands by `gain` times the relative difference of their
// (smoothed) times, times the two bands' rows. Every band keeps at least one row. busy[t] is
// thread t's time; smoothed carries the exponential average between calls (weight `keep` on
// the past). The pixels do not depend on the edges, only how the work is split does. The
// defaults are slow on purpose: a core that is much slower for a few milliseconds now and then
// (a busy host) is not chased.
void balance_bands(std::vector<double>& edge, const double* busy, std::vector<double>& smoothed, double gain = 0.1,
                   double keep = 0.95);

// The smallest and largest y of n screen points, breaks (kBreak) left out: {INT32_MAX,
// INT32_MIN} when there is no point. Both are maxima: the top is minus the largest -y, and a
// break's y, INT32_MIN, is its own negative (mod 2^32), the least of both, so no point needs a
// test and the loop vectorises (SSE2, NEON). Negating any other y does not wrap. (A y of
// INT32_MIN is taken for a break whatever its x.)
struct RowSpan {
    int32_t top, bottom;
};
inline RowSpan row_span(const SubPoint* pts, std::size_t n) {
    static_assert(kBreak.y == INT32_MIN);
    int32_t up = INT32_MIN, down = INT32_MIN;  // the largest -y and y
    for (std::size_t k = 0; k < n; ++k) {
        const int32_t y = pts[k].y;
        up = std::max(up, static_cast<int32_t>(0u - static_cast<uint32_t>(y))), down = std::max(down, y);
    }
    return {up == INT32_MIN ? INT32_MAX : -up, down};
}

namespace detail {

// One frame's bands: thread t draws rows [row[t], row[t + 1]).
struct FrameBands {
    int threads = 0;
    uint32_t generation = 0;
    int64_t margin = 0;  // a body's pixels lie within its points' rows widened by this (row_margin)
    int width = 0, height = 0;  // the canvas's (a fill's rows and columns are clipped to it)
    int row[kMaxBandThreads + 1] = {};
    // Whether a body whose points span rows [top, bottom] (1/256 px) can put pixels in band k.
    bool reaches(int k, int32_t top, int32_t bottom) const {
        return bottom >= int64_t{row[k]} * kSub - margin && top < int64_t{row[k + 1]} * kSub + margin;
    }
    // The band that holds pixel row y (the first band for rows above, the last below).
    int band_of(int64_t y) const {
        int k = 0;
        while (k + 1 < threads && y >= row[k + 1]) ++k;
        return k;
    }
};

// Sets up a frame's bands on a canvas `height` rows high for lines drawn in `line`: equal
// bands first (and whenever the height or the pool changed), the rounded edges, the next
// generation. parallel_frame.cpp.
void start_frame(ParallelScratchBase& s, int height, int threads, LineStyle line, FrameBands& f);

// What one band's raster needs of the frame.
struct BandRaster {
    const Canvas& canvas;
    LimitCircle circle;
    const DrawOptions& options;
    bool backdrop;
    LineStyle line;
    RowWork* fill_work;  // thread t's is fill_work[t]
};
// Thread t's raster (parallel_frame.cpp): band t's backdrop, then the bodies that reach it, in
// the world's order, from the threads' lists for it. Returns the time it waited for them.
std::chrono::steady_clock::duration raster_band(const BandRaster& r, const ParallelScratchBase& s, const FrameBands& f,
                                                int t);

// After the frame: the band edges balanced by the threads' busy times.
void finish_frame(ParallelScratchBase& s, int threads);

// Thread t's geometry: the screen points of its home bodies into its arena, each body entered
// in this thread's list for every band it reaches, and its home for the next frame; then every
// list closed.
template <class W>
void geometry_of_thread(const W& world, const ScreenMap<typename W::scalar>& m, const DrawOptions& o,
                        ParallelScratch<typename W::scalar, typename W::engine>& s, const FrameBands& f, int t) {
    using T = typename W::scalar;
    const int threads = f.threads;
    const uint32_t gen = f.generation;
    geo::Polar<T>* verts = s.vertices.data() + s.stride_v * static_cast<std::size_t>(t);
    geo::Vec3<T>* vecs = s.vectors.data() + s.stride_vec * static_cast<std::size_t>(t);
    SubPoint* arena = s.points.data() + s.stride_points * static_cast<std::size_t>(t);
    BandEntry* list[kMaxBandThreads];  // this thread's list for band k, and its length
    uint32_t listed[kMaxBandThreads];
    for (int k = 0; k < threads; ++k) list[k] = s.list(t, k, threads), listed[k] = 0;
    const uint8_t* home = s.home[gen & 1].data();
    uint8_t* next_home = s.home[(gen + 1) & 1].data();
    const int nb = static_cast<int>(std::min(s.bodies, world.bodies.size()));
    auto next_body = [home, nb, t](int i) {  // this thread's next body after i (nb: none)
        do ++i;
        while (i < nb && home[i] != t);
        return i;
    };
    // The body two ahead is fetched while this one is done: World::step has just written every
    // body on the calling thread's core, and a thread's bodies are not contiguous, so the
    // hardware prefetchers do not see them coming.
    constexpr int kAhead = 2;
    int ahead = -1;
    for (int k = 0; k <= kAhead; ++k) ahead = next_body(ahead);
    for (int i = next_body(-1); i < nb; i = next_body(i)) {
        if (ahead < nb) {
            __builtin_prefetch(&world.bodies[static_cast<std::size_t>(ahead)]);
            ahead = next_body(ahead);
        }
        const std::size_t idx = static_cast<std::size_t>(i);
        const auto& b = world.bodies[idx];
        SubPoint* pts = arena;
        const bool shown = body_shown(b, o);
        const std::size_t n = shown ? body_screen_points(world, b, s.shapes[idx], m, o, verts, vecs, pts) : 0;
        RowSpan span = row_span(pts, n);
        const FillJob* fj = shown ? s.fill.plan(world, idx, m, o, f.width, f.height) : nullptr;
        if (fj) span = {std::min(span.top, fj->top * kSub), std::max(span.bottom, fj->bottom * kSub - 1)};
        // Next frame's home: the band of the points' middle row. Written only when it changes
        // (rarely): the threads' bodies share these cache lines.
        const uint8_t h = span.top <= span.bottom
                              ? static_cast<uint8_t>(f.band_of((int64_t{span.top} + span.bottom) / 2 / kSub))
                              : home[idx];
        if (next_home[idx] != h) next_home[idx] = h;
        for (int k = 0; k < threads && (n > 0 || fj); ++k) {
            if (!f.reaches(k, span.top, span.bottom)) continue;
            BandEntry& e = list[k][listed[k]++];
            e.top = span.top, e.bottom = span.bottom, e.count = static_cast<uint32_t>(n), e.idx = static_cast<uint32_t>(idx);
            e.points = pts, e.color = body_color(b, o), e.fill = fj;
            e.ready.store(gen, std::memory_order_release);
        }
        arena += ParallelScratchBase::arena_step(n);
    }
    for (int k = 0; k < threads; ++k) {  // close the lists
        BandEntry& e = list[k][listed[k]];
        e.idx = BandEntry::kEnd;
        e.ready.store(gen, std::memory_order_release);
    }
}

// The frame on the calling thread alone, with thread 0's buffers: a pool too large to band, or
// a canvas with fewer rows than threads.
template <class W>
void draw_unbanded(const Canvas& c, const W& world, const ScreenMap<typename W::scalar>& m, const DrawOptions& o,
                   ParallelScratch<typename W::scalar, typename W::engine>& s, bool backdrop) {
    if (backdrop) draw_backdrop(c, m, o);
    s.fill.begin_frame(c);
    const std::size_t nb = std::min(s.bodies, world.bodies.size());
    for (std::size_t i = 0; i < nb; ++i) {
        const auto& b = world.bodies[i];
        if (!body_shown(b, o)) continue;
        if (const FillJob* j = s.fill.plan(world, i, m, o, c.width(), c.height())) fill_rows(c, *j, 0, c.height(), s.fill.work[0]);
        const std::size_t n =
            body_screen_points(world, b, s.shapes[i], m, o, s.vertices.data(), s.vectors.data(), s.points.data());
        draw_screen_points(c, s.points.data(), n, body_color(b, o), LineStyle{o.antialias, o.line_width});
    }
}

}  // namespace detail

// The frame of draw_world(c, world, o, DrawScratch&), pixel for pixel, over the pool's threads
// (the header comment). The scratch must have been prepared for this world and this pool.
template <class W>
void draw_world(const Canvas& c, const W& world, const DrawOptions& o, ParallelScratch<typename W::scalar, typename W::engine>& s,
                WorkerPool& pool, bool backdrop = true) {
    using T = typename W::scalar;
    using clock = std::chrono::steady_clock;
    ScreenMap<T> m = ScreenMap<T>::of(c, world.K, world.R, o.projection, o.disc);
    if (s.any_detail) set_detail(m, s.detail, world.K, world.R, o.projection);
    const int threads = pool.size();
    if (threads > kMaxBandThreads || c.height() < threads) return detail::draw_unbanded(c, world, m, o, s, backdrop);
    const LineStyle line{o.antialias, o.line_width};
    detail::FrameBands bands;
    detail::start_frame(s, c.height(), threads, line, bands);
    bands.width = c.width(), bands.height = c.height();
    s.fill.begin_frame(c);
    const detail::BandRaster raster{c, limit_circle(m), o, backdrop, line, s.fill.work.data()};
    auto job = [&](int t) {
        const clock::time_point started = clock::now();
        detail::geometry_of_thread(world, m, o, s, bands, t);
        const clock::time_point geometry_done = clock::now();
        const clock::duration waited = detail::raster_band(raster, s, bands, t);
        auto seconds = [](clock::duration d) { return std::chrono::duration<double>(d).count(); };
        ParallelScratchBase::Busy& mine = s.busy[static_cast<std::size_t>(t)];
        mine.seconds = seconds(clock::now() - started - waited);
        mine.geometry = seconds(geometry_done - started), mine.waited = seconds(waited);
    };
    pool.run(job);
    detail::finish_frame(s, threads);
}

}  // namespace noneuclid::render
