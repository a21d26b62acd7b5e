// `noneuclid accuracy`: every fixed-point function against std:: double, then the geometry
// engines at the screen, as tables; exit status 1 if a row misses its bound.
#include <cstdint>
#include <cstdio>
#include <vector>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "app/options.hpp"
#include "fixed/accuracy.hpp"
#include "fixed/tables.hpp"
#include "geometry/accuracy.hpp"

namespace noneuclid::app {

namespace {

const char* format_arg(char* buf, std::size_t n, const fx::AccuracyRow& r,
                       const double* arg) {
    if (r.two_args)
        std::snprintf(buf, n, "(%.6g, %.6g)", arg[0], arg[1]);
    else
        std::snprintf(buf, n, "%.9g", arg[0]);
    return buf;
}

// The geometry engines at the screen: a 1080-px disk, limit radius pi = 540 px.
bool print_geometry_report() {
    using namespace geo;
    const GeometryReportOptions o;
    std::vector<ScreenErrorRow> rows(static_cast<std::size_t>(screen_error_row_count()));
    const int n = measure_screen_error(o, rows.data(), static_cast<int>(rows.size()));
    std::printf("\ngeometry at the screen: 1080-px disk (limit radius pi = 540 px), azimuthal "
                "equidistant;\n%d random bodies per K (centres inside the limit circle, edges at "
                "tessellation level 8),\nK swept over [-1, 1] in %d steps unless said; error in px "
                "against the engine named\n\n",
                o.bodies, o.k_steps);
    std::printf("%-7s %-9s %-12s %-20s %8s %5s  %-9s %-9s %-9s %-9s %-15s %-9s %s\n", "engine", "against",
                "points", "where", "samples", "NaN", "max px", "median", "p99", "p99.9", "max at K, r",
                "bound", "ok");
    bool all = true;
    for (int i = 0; i < n; ++i) {
        const ScreenErrorRow& r = rows[static_cast<std::size_t>(i)];
        char at[40], bound[16];
        std::snprintf(at, sizeof at, "%.4g, %.3g", r.at_K, r.at_r);
        if (r.bound_px > 0)
            std::snprintf(bound, sizeof bound, "%.2g", r.bound_px);
        else
            std::snprintf(bound, sizeof bound, "-");
        std::printf("%-7s %-9s %-12s %-20s %8ld %5ld  %-9.3g %-9.3g %-9.3g %-9.3g %-15s %-9s %s\n", r.engine,
                    r.against, r.what, r.where, r.samples, r.nonfinite, r.max_px, r.p50_px, r.p99_px,
                    r.p999_px, at, bound, r.bound_px > 0 ? (r.pass ? "yes" : "NO") : "-");
        all = all && r.pass;
    }
    std::vector<ContinuityRow> cont(static_cast<std::size_t>(continuity_row_count()));
    const int m = measure_continuity(o, cont.data(), static_cast<int>(cont.size()));
    std::printf("\ncontinuity through K = 0: the largest screen movement of any point of the scene\n\n");
    std::printf("%-22s %-46s %-10s %-9s %s\n", "engine", "between", "max px", "bound", "ok");
    for (int i = 0; i < m; ++i) {
        const ContinuityRow& r = cont[static_cast<std::size_t>(i)];
        char bound[16];
        if (r.bound_px > 0)
            std::snprintf(bound, sizeof bound, "%.2g", r.bound_px);
        else
            std::snprintf(bound, sizeof bound, "-");
        std::printf("%-22s %-46s %-10.3g %-9s %s\n", r.engine, r.what, r.max_px, bound,
                    r.bound_px > 0 ? (r.pass ? "yes" : "NO") : "-");
        all = all && r.pass;
    }
    std::vector<ShortDistanceRow> sd(static_cast<std::size_t>(short_distance_row_count()));
    const int k = measure_short_distance(o, sd.data(), static_cast<int>(sd.size()));
    std::printf("\nshort distances: relative error of the distance between two points this far apart,\n"
                "K in {-1, -0.5, -0.02, 0.02, 0.5, 1} (paper: acos/acosh of the law of cosines, no flat "
                "branch;\nfixed: error over the length, against the reference on the same rounded points; Q16.16 has\n"
                "no digits to spare below 1e-3, where one step is 1.5e-5)\n\n");
    std::printf("%-8s %-8s %-12s %s\n", "engine", "length", "max rel err", "NaN");
    for (int i = 0; i < k; ++i) {
        const ShortDistanceRow& r = sd[static_cast<std::size_t>(i)];
        std::printf("%-8s %-8.0e %-12.3g %ld\n", r.engine, r.length, r.max_rel, r.nonfinite);
    }
    return all;
}

int run_accuracy(const fx::AccuracyOptions& options) {
    using fx::AccuracyRow;
    std::vector<AccuracyRow> rows(static_cast<std::size_t>(fx::accuracy_row_count()));
    const int n = fx::measure_accuracy(options, rows.data(), static_cast<int>(rows.size()));

    std::printf("noneuclid %s: fixed-point (Q16.16, binary angle) functions against std:: double\n",
                version());
    std::printf("samples per row: %ld evenly spaced (+%ld log-spaced where marked ~) + %ld random "
                "(seed %llu)\n",
                options.dense, options.dense, options.random,
                static_cast<unsigned long long>(options.seed));
    std::printf("rows with a floor: relative error where |reference| >= floor, absolute below it;\n"
                "other rows: absolute error everywhere. Errors in radians for angles.\n"
                "bound: what this report checks (tests/accuracy holds its own); required: the ceiling asked for.\n\n");
    std::printf("%-15s %-19s %8s  %-10s %-18s  %-10s %-18s %-5s  %-21s %-9s %s\n", "function",
                "domain", "samples", "max abs", "at", "max rel", "at", "floor", "bound",
                "required", "ok");
    bool all = true;
    for (int i = 0; i < n; ++i) {
        const AccuracyRow& r = rows[static_cast<std::size_t>(i)];
        char a1[48], a2[48], rel[16], bound[40], req[16], floor_[24];
        const bool has_rel = r.rel_floor > 0 || r.rel_bound > 0;
        if (has_rel) {
            std::snprintf(rel, sizeof rel, "%.2e", r.max_rel);
            format_arg(a2, sizeof a2, r, r.arg_rel);
            std::snprintf(floor_, sizeof floor_, "%g", r.rel_floor);
        } else {
            std::snprintf(rel, sizeof rel, "-");
            std::snprintf(a2, sizeof a2, "-");
            std::snprintf(floor_, sizeof floor_, "-");
        }
        if (r.abs_bound > 0 && r.rel_bound > 0)
            std::snprintf(bound, sizeof bound, "abs %.1e, rel %.1e", r.abs_bound, r.rel_bound);
        else if (r.abs_bound > 0)
            std::snprintf(bound, sizeof bound, "abs %.1e", r.abs_bound);
        else
            std::snprintf(bound, sizeof bound, "rel %.1e", r.rel_bound);
        if (r.required > 0)
            std::snprintf(req, sizeof req, "%s %.0e", r.required_is_rel ? "rel" : "abs", r.required);
        else
            std::snprintf(req, sizeof req, "-");
        char abs_[16];
        if (r.abs_samples > 0) {
            std::snprintf(abs_, sizeof abs_, "%.2e", r.max_abs);
            format_arg(a1, sizeof a1, r, r.arg_abs);
        } else {
            std::snprintf(abs_, sizeof abs_, "-");
            std::snprintf(a1, sizeof a1, "-");
        }
        std::printf("%-15s %-19s %8ld  %-10s %-18s  %-10s %-18s %-5s  %-21s %-9s %s\n",
                    r.function, r.domain, r.samples, abs_, a1, rel, a2, floor_, bound, req,
                    r.pass ? "yes" : "NO");
        all = all && r.pass;
    }
    std::printf("\nlookup tables: %zu bytes (%.1f KiB) of read-only data, built at compile time\n",
                fx::tables::table_bytes,
                static_cast<double>(fx::tables::table_bytes) / 1024.0);
    all = print_geometry_report() && all;
    std::printf("\n%s\n", all ? "all rows within their bounds"
                              : "SOME ROWS MISS THEIR BOUNDS (marked NO)");
    return all ? 0 : 1;
}

}  // namespace

int accuracy_command(int argc, char** argv, int first) {
    Options o = defaults(Command::accuracy);
    Args args(argc, argv, first);
    parse_options(args, o, Command::accuracy);
    return run_accuracy(o.accuracy);
}

}  // namespace noneuclid::app
