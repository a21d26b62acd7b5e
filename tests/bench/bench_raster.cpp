// The line rasteriser against Cairo (image surface, pixman), measured side by side in one run
// (Google Benchmark), with a summary table of ms per 100k segments and Cairo/ours ratios.
//     build/release/bench_raster --benchmark_repetitions=5   (the table takes the fastest of each)
//     build/release/bench_raster --benchmark_filter=aliased
//
// Workload: 100,000 segments, each 50 px long, from a random start inside a 1280x720 canvas in
// a random direction (a fixed mt19937 sequence; ends outside the canvas get clipped, the same
// for both). The coordinates are quantised to 1/256 px once, so both libraries draw exactly
// the same geometry: ours gets SubPoints, Cairo the same values as doubles. One colour, opaque.
// Canvas: XRGB8888; Cairo draws into the same kind of buffer as a CAIRO_FORMAT_RGB24 image
// surface (XRGB8888 in memory on a little-endian machine).
//
// One benchmark iteration draws all 100,000 segments, so the reported time is ms per 100k
// segments. The canvas is cleared before each iteration with the timer paused (both sides).
//   ours_aliased        draw_line, LineStyle{false, 256}
//   cairo_aliased       CAIRO_ANTIALIAS_NONE, width 1, butt caps; move_to/line_to/stroke per segment
//   cairo_aliased_path  the same, but all segments in one path and a single stroke
//   ours_antialiased    draw_line, LineStyle{true, 256}
//   cairo_antialiased   CAIRO_ANTIALIAS_DEFAULT, width 1, butt caps; one stroke per segment
//   cairo_antialiased_path  the same in one path (one stroke: overlaps are composited once,
//                       so it does less blending than per-segment drawing; shown for reference)
//
// Before timing, the aliased case is checked once for comparable work: every segment is drawn
// alone and its lit pixels counted (then cleared), for both libraries; the sums must agree
// within 25% or the program exits 1.
#include <benchmark/benchmark.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "fastest.hpp"
#include "render/canvas.hpp"
#include "render/raster.hpp"

namespace nr = noneuclid::render;

namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr int kSegments = 100'000;
constexpr double kLength = 50.0;  // px
constexpr nr::Rgb kColor{255, 200, 64};
constexpr std::uint32_t kSeed = 20240601;

struct Segment {
    nr::SubPoint a, b;              // 1/256 px
    double ax, ay, bx, by;          // the same points in px, for Cairo
};

// The fixed sequence: raw mt19937 words (fully specified by the standard), so every standard
// library gives the same segments.
const std::vector<Segment>& segments() {
    static const std::vector<Segment> all = [] {
        std::mt19937 rng(kSeed);
        auto unit = [&rng] { return static_cast<double>(rng()) / 4294967296.0; };  // [0, 1)
        std::vector<Segment> v;
        v.reserve(kSegments);
        for (int i = 0; i < kSegments; ++i) {
            const double x = unit() * kWidth, y = unit() * kHeight;
            const double t = unit() * 2 * std::acos(-1.0);
            const nr::SubPoint a = nr::to_sub(x, y);
            const nr::SubPoint b = nr::to_sub(x + kLength * std::cos(t), y + kLength * std::sin(t));
            v.push_back({a, b, a.x / double(nr::kSub), a.y / double(nr::kSub), b.x / double(nr::kSub),
                         b.y / double(nr::kSub)});
        }
        return v;
    }();
    return all;
}

// A 1280x720 XRGB8888 buffer (stride 5120 bytes, which is also Cairo's stride for RGB24).
struct Buffer {
    std::vector<std::uint32_t> px = std::vector<std::uint32_t>(std::size_t{kWidth} * kHeight, 0);
    static constexpr std::ptrdiff_t stride = kWidth * 4;
    void clear() { std::fill(px.begin(), px.end(), 0u); }
    nr::Canvas canvas() { return nr::Canvas(px.data(), kWidth, kHeight, stride, nr::PixelFormat::xrgb8888()); }
};

// Cairo over a Buffer.
struct CairoTarget {
    cairo_surface_t* surface;
    cairo_t* cr;
    CairoTarget(Buffer& buf, cairo_antialias_t aa) {
        if (cairo_format_stride_for_width(CAIRO_FORMAT_RGB24, kWidth) != Buffer::stride) std::abort();
        surface = cairo_image_surface_create_for_data(reinterpret_cast<unsigned char*>(buf.px.data()),
                                                      CAIRO_FORMAT_RGB24, kWidth, kHeight, Buffer::stride);
        cr = cairo_create(surface);
        cairo_set_source_rgb(cr, kColor.r / 255.0, kColor.g / 255.0, kColor.b / 255.0);
        cairo_set_antialias(cr, aa);
        cairo_set_line_width(cr, 1.0);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
        cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
        if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) std::abort();
    }
    ~CairoTarget() {
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
    }
    CairoTarget(const CairoTarget&) = delete;
    CairoTarget& operator=(const CairoTarget&) = delete;

    void stroke(const Segment& s) {
        cairo_move_to(cr, s.ax, s.ay);
        cairo_line_to(cr, s.bx, s.by);
        cairo_stroke(cr);
    }
    void stroke_all_in_one_path(const std::vector<Segment>& segs) {
        for (const Segment& s : segs) {
            cairo_move_to(cr, s.ax, s.ay);
            cairo_line_to(cr, s.bx, s.by);
        }
        cairo_stroke(cr);
    }
    // Around writing the buffer directly (clearing, counting).
    void before_direct_access() { cairo_surface_flush(surface); }
    void after_direct_access() { cairo_surface_mark_dirty(surface); }
};

void run_ours(benchmark::State& st, bool antialias) {
    const std::vector<Segment>& segs = segments();
    Buffer buf;
    const nr::Canvas canvas = buf.canvas();
    const nr::LineStyle style{antialias, nr::kSub};
    for (auto _ : st) {
        st.PauseTiming();
        buf.clear();
        st.ResumeTiming();
        for (const Segment& s : segs) nr::draw_line(canvas, s.a, s.b, kColor, style, true);
        benchmark::DoNotOptimize(buf.px.data());
        benchmark::ClobberMemory();
    }
    st.counters["segments"] = kSegments;
}

void run_cairo(benchmark::State& st, cairo_antialias_t aa, bool one_path) {
    const std::vector<Segment>& segs = segments();
    Buffer buf;
    CairoTarget target(buf, aa);
    for (auto _ : st) {
        st.PauseTiming();
        target.before_direct_access();
        buf.clear();
        target.after_direct_access();
        st.ResumeTiming();
        if (one_path)
            target.stroke_all_in_one_path(segs);
        else
            for (const Segment& s : segs) target.stroke(s);
        cairo_surface_flush(target.surface);  // any deferred drawing lands in the buffer
        benchmark::DoNotOptimize(buf.px.data());
        benchmark::ClobberMemory();
    }
    if (cairo_status(target.cr) != CAIRO_STATUS_SUCCESS) st.SkipWithError(cairo_status_to_string(cairo_status(target.cr)));
    st.counters["segments"] = kSegments;
}

void ours_aliased(benchmark::State& st) { run_ours(st, false); }
void ours_antialiased(benchmark::State& st) { run_ours(st, true); }
void cairo_aliased(benchmark::State& st) { run_cairo(st, CAIRO_ANTIALIAS_NONE, false); }
void cairo_aliased_path(benchmark::State& st) { run_cairo(st, CAIRO_ANTIALIAS_NONE, true); }
void cairo_antialiased(benchmark::State& st) { run_cairo(st, CAIRO_ANTIALIAS_DEFAULT, false); }
void cairo_antialiased_path(benchmark::State& st) { run_cairo(st, CAIRO_ANTIALIAS_DEFAULT, true); }

// ---------------------------------------------------------------------------------------------
// Comparable work: lit pixels of the aliased segments, each drawn alone.
// ---------------------------------------------------------------------------------------------
struct Counts {
    long long per_segment_sum = 0;  // sum over segments of the pixels each lights on its own
    long long union_lit = 0;        // pixels lit after drawing all segments on one canvas
};

// Counts and clears the lit pixels in a segment's bounding box grown by 2 px (nothing a
// 1-px line draws lies further out).
long long count_and_clear(Buffer& buf, const Segment& s) {
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(s.ax, s.bx))) - 2);
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(s.ay, s.by))) - 2);
    const int x1 = std::min(kWidth - 1, static_cast<int>(std::floor(std::max(s.ax, s.bx))) + 2);
    const int y1 = std::min(kHeight - 1, static_cast<int>(std::floor(std::max(s.ay, s.by))) + 2);
    long long n = 0;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            std::uint32_t& p = buf.px[std::size_t(y) * kWidth + x];
            if ((p & 0xFFFFFF) != 0) ++n, p = 0;
        }
    return n;
}

long long count_lit(const Buffer& buf) {
    return std::count_if(buf.px.begin(), buf.px.end(), [](std::uint32_t p) { return (p & 0xFFFFFF) != 0; });
}

Counts count_ours() {
    const std::vector<Segment>& segs = segments();
    Buffer buf;
    const nr::Canvas canvas = buf.canvas();
    Counts c;
    for (const Segment& s : segs) {
        nr::draw_line(canvas, s.a, s.b, kColor, nr::LineStyle{false, nr::kSub}, true);
        c.per_segment_sum += count_and_clear(buf, s);
    }
    if (count_lit(buf) != 0) std::abort();  // something was drawn outside the boxes
    for (const Segment& s : segs) nr::draw_line(canvas, s.a, s.b, kColor, nr::LineStyle{false, nr::kSub}, true);
    c.union_lit = count_lit(buf);
    return c;
}

Counts count_cairo() {
    const std::vector<Segment>& segs = segments();
    Buffer buf;
    CairoTarget target(buf, CAIRO_ANTIALIAS_NONE);
    Counts c;
    for (const Segment& s : segs) {
        target.stroke(s);
        target.before_direct_access();
        c.per_segment_sum += count_and_clear(buf, s);
        target.after_direct_access();
    }
    if (count_lit(buf) != 0) std::abort();
    for (const Segment& s : segs) target.stroke(s);
    target.before_direct_access();
    c.union_lit = count_lit(buf);
    return c;
}

// The summary: ms per 100k segments, the fastest repetition of each (fastest.hpp), and the
// ratios of Cairo's to ours.
std::map<std::string, double> g_ms;
double ms_of(const std::string& name) {
    const auto it = g_ms.find(name);
    return it == g_ms.end() ? NAN : it->second;
}
void ratio_row(const char* label, const char* o, const char* c, const char* c1, double goal) {
    const double ours_ms = ms_of(o), cairo_ms = ms_of(c), cairo1_ms = ms_of(c1);
    if (std::isnan(ours_ms) && std::isnan(cairo_ms) && std::isnan(cairo1_ms)) return;
    std::printf("%-14s %10.2f %12.2f %12.2f %12.2f %14.2f   (goal cairo/ours >= %g)\n", label, ours_ms, cairo_ms,
                cairo_ms / ours_ms, cairo1_ms, cairo1_ms / ours_ms, goal);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::RegisterBenchmark("ours_aliased", ours_aliased)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("cairo_aliased", cairo_aliased)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("cairo_aliased_path", cairo_aliased_path)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("ours_antialiased", ours_antialiased)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("cairo_antialiased", cairo_antialiased)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("cairo_antialiased_path", cairo_antialiased_path)->Unit(benchmark::kMillisecond);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

    // Comparable work, checked once before any timing.
    const Counts o = count_ours(), c = count_cairo();
    const double ratio = static_cast<double>(c.per_segment_sum) / static_cast<double>(o.per_segment_sum);
    std::printf("aliased lit pixels, %d segments each drawn alone (sum): ours %lld, cairo %lld, cairo/ours %.3f\n",
                kSegments, o.per_segment_sum, c.per_segment_sum, ratio);
    std::printf("aliased lit pixels, all segments on one %dx%d canvas: ours %lld, cairo %lld\n", kWidth, kHeight,
                o.union_lit, c.union_lit);
    if (!(ratio >= 0.75 && ratio <= 1.25)) {
        std::fprintf(stderr, "bench_raster: the two libraries lit pixel counts more than 25%% apart\n");
        return 1;
    }

    FastestReporter reporter([](const std::string& name, const benchmark::BenchmarkReporter::Run& r) {
        if (!r.error_occurred) keep_fastest(g_ms, name, r.GetAdjustedCPUTime());  // in the benchmarks' unit: ms
    });
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    std::printf("\nms per 100k segments of 50 px (CPU time, the fastest of the repetitions), same run; ratio > 1 means "
                "ours is faster\n");
    std::printf("%-14s %10s %12s %12s %12s %14s\n", "lines", "ours", "cairo", "cairo/ours", "cairo 1path", "cairo1p/ours");
    ratio_row("aliased", "ours_aliased", "cairo_aliased", "cairo_aliased_path", 10);
    ratio_row("anti-aliased", "ours_antialiased", "cairo_antialiased", "cairo_antialiased_path", 10);
    return 0;
}
