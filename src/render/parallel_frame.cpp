#include "render/parallel_frame.hpp"

#include <cmath>

namespace noneuclid::render {

uint32_t ParallelScratchBase::next_generation() {
    if (++generation == 0) {
        for (std::size_t i = 0; i < list_entries; ++i) lists[i].ready.store(0, std::memory_order_relaxed);
        generation = 1;
    }
    return generation;
}

void ParallelScratchBase::prepare_bands(std::size_t body_count, std::size_t arena, int threads) {
    const std::size_t n = static_cast<std::size_t>(threads);
    bodies = body_count;
    stride_points = arena + 16;  // and two lines between arenas (their starts need not be on a line)
    points.resize(stride_points * n);
    stride_list = bodies + 1 + (64 + sizeof(BandEntry) - 1) / sizeof(BandEntry);
    list_entries = stride_list * n * n;
    lists.reset(new BandEntry[list_entries]);
    for (auto& h : home) {
        h.resize(bodies);
        for (std::size_t i = 0; i < bodies; ++i) h[i] = static_cast<uint8_t>(i % n);
    }
    generation = 0;
    edge.clear();
    edge.reserve(n + 1);  // (set by the first frame: no allocation there)
    busy.reset(new Busy[n]);
    smoothed.assign(n, 0.0);
}

void balance_bands(std::vector<double>& edge, const double* busy, std::vector<double>& smoothed, double gain,
                   double keep) {
    const std::size_t bands = edge.size() - 1;
    for (std::size_t t = 0; t < bands; ++t)
        smoothed[t] = smoothed[t] > 0 ? keep * smoothed[t] + (1 - keep) * busy[t] : busy[t];
    for (std::size_t k = 1; k < bands; ++k) {
        const double a = smoothed[k - 1], b = smoothed[k];
        if (!(a + b > 0)) continue;
        const double lo = edge[k - 1] + 1, hi = edge[k + 1] - 1;
        if (lo > hi) continue;
        edge[k] = std::clamp(edge[k] - gain * (a - b) / (a + b) * (edge[k + 1] - edge[k - 1]), lo, hi);
    }
}

namespace detail {

void start_frame(ParallelScratchBase& s, int height, int threads, LineStyle line, FrameBands& f) {
    const std::size_t n = static_cast<std::size_t>(threads);
    if (s.edge.size() != n + 1 || s.edge.back() != height) {
        s.edge.resize(n + 1);
        for (int t = 0; t <= threads; ++t) s.edge[static_cast<std::size_t>(t)] = double(height) * t / threads;
    }
    f.threads = threads;
    for (int t = 0; t <= threads; ++t) f.row[t] = static_cast<int>(std::lround(s.edge[static_cast<std::size_t>(t)]));
    f.generation = s.next_generation();
    f.margin = row_margin(line);
}

namespace {
// The lists' merge: of the threads' next entries for band t, the one with the least body
// index (the world's order), taken from its list; nullptr once every list is closed. Waits
// (yielding) for an entry its thread has not written yet, adding the time to `waited`.
const BandEntry* next_in_world_order(const BandEntry** head, const FrameBands& f,
                                     std::chrono::steady_clock::duration& waited) {
    using clock = std::chrono::steady_clock;
    int first = -1;  // the thread whose next entry has the least idx
    uint32_t least = BandEntry::kEnd;
    for (int u = 0; u < f.threads; ++u) {
        const BandEntry& e = *head[u];
        if (e.ready.load(std::memory_order_acquire) != f.generation) {
            const clock::time_point w0 = clock::now();
            while (e.ready.load(std::memory_order_acquire) != f.generation) WorkerPool::pause();
            waited += clock::now() - w0;
        }
        if (e.idx < least) least = e.idx, first = u;
    }
    return first < 0 ? nullptr : head[first]++;
}
}  // namespace

std::chrono::steady_clock::duration raster_band(const BandRaster& r, const ParallelScratchBase& s, const FrameBands& f,
                                                int t) {
    std::chrono::steady_clock::duration waited{0};
    const int y0 = f.row[t], y1 = f.row[t + 1];
    if (r.backdrop) draw_backdrop_rows(r.canvas, r.circle, r.options, y0, y1);
    const BandEntry* head[kMaxBandThreads];  // each thread's next entry for this band
    for (int u = 0; u < f.threads; ++u) head[u] = s.list(u, t, f.threads);
    while (const BandEntry* e = next_in_world_order(head, f, waited)) {
        // A body wholly inside the band (its margin too) writes only there: drawn as on one
        // thread, without the band's per-segment checks.
        if (e->fill) fill_rows(r.canvas, *e->fill, y0, y1, r.fill_work[t]);
        const bool inside = e->top - f.margin >= int64_t{y0} * kSub && e->bottom + f.margin < int64_t{y1} * kSub;
        draw_screen_points(r.canvas, e->points, e->count, e->color, r.line, inside ? RowRange{} : RowRange{y0, y1});
    }
    return waited;
}

void finish_frame(ParallelScratchBase& s, int threads) {
    if (!s.balance) return;
    double busy[kMaxBandThreads];
    for (int t = 0; t < threads; ++t) busy[t] = s.busy[static_cast<std::size_t>(t)].seconds;
    balance_bands(s.edge, busy, s.smoothed);
}

}  // namespace detail

}  // namespace noneuclid::render
