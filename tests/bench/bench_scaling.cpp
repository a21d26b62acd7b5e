// Frame cost over bodies s, vertices v and tessellation i (the paper's O(s v i)), side by side in
// one run (Google Benchmark), fixed and double engines:
//     build/release/bench_scaling [--svg=scaling.svg]
// The stress scene (K = -1, random bodies) with s bodies of v vertices at level i, 800x480
// RGB565, drawn without the backdrop (a constant per frame, measured in bench_breakdown):
//   geometry  every body's screen points (vertices, edges, projection)
//   draw      geometry + raster (draw_world, backdrop off)
// Three sweeps through (s, v, i) = (100, 8, 8): s in 25..400, v in 4..32, i in 1..32, and v in
// 4..32 at i = 1 (vertices alone). A least-squares fit t = c0 + c_b s + c_vx (s v) + c_pt (s v i)
// per engine and stage follows (per body, per vertex, per tessellated point), with the table of
// every point against the fit, and an SVG plot of us against s v i if --svg is given.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "render/draw_world.hpp"
#include "fastest.hpp"

namespace {

using namespace noneuclid;

struct Point {
    int s, v, i;
};
std::map<std::string, double> g_us;

template <class T>
void run(benchmark::State& st, Point p, bool raster) {
    world::Scene scene;
    world::builtin_scene("stress", {p.s, p.v, p.i}, scene);
    world::World<T> wd(scene);
    render::DrawScratch<T> scratch;
    scratch.prepare(wd);
    for (int k = 0; k < 10; ++k) wd.step(1.0 / 60);
    std::vector<uint8_t> px(800 * 480 * 2);
    const render::Canvas c(px.data(), 800, 480, 1600, render::PixelFormat::rgb565());
    const render::DrawOptions o;
    const auto m = render::ScreenMap<T>::of(c, wd.K, wd.R, o.projection);
    for (auto _ : st) {
        if (raster)
            render::draw_world(c, wd, o, scratch, false);
        else
            for (std::size_t i = 0; i < wd.bodies.size(); ++i)
                benchmark::DoNotOptimize(render::body_screen_points(wd, wd.bodies[i], scratch.shapes[i], m, o, scratch.vertices.data(),
                                                                    scratch.vectors.data(), scratch.points.data()));
        benchmark::ClobberMemory();
    }
    st.counters["points"] = static_cast<double>(p.s) * p.v * p.i;
}

std::string key(const char* e, const char* stage, Point p) {
    char b[96];
    std::snprintf(b, sizeof b, "%s/%s/s%d_v%d_i%d", e, stage, p.s, p.v, p.i);
    return b;
}

// Least squares for t = sum_j c_j x_j (normal equations, Gaussian elimination with partial
// pivoting): N = 4 for the fit, 2 for the slope of the i = 1 runs.
template <int N>
void fit(const std::vector<std::array<double, N>>& x, const std::vector<double>& t, double c[N]) {
    double A[N][N + 1] = {};
    for (std::size_t k = 0; k < t.size(); ++k)
        for (int i = 0; i < N; ++i) {
            A[i][N] += x[k][i] * t[k];
            for (int j = 0; j < N; ++j) A[i][j] += x[k][i] * x[k][j];
        }
    for (int col = 0; col < N; ++col) {
        int piv = col;
        for (int r = col + 1; r < N; ++r)
            if (std::fabs(A[r][col]) > std::fabs(A[piv][col])) piv = r;
        for (int j = 0; j <= N; ++j) std::swap(A[col][j], A[piv][j]);
        for (int r = col + 1; r < N; ++r) {
            const double f = A[r][col] / A[col][col];
            for (int j = col; j <= N; ++j) A[r][j] -= f * A[col][j];
        }
    }
    for (int i = N - 1; i >= 0; --i) {
        double v = A[i][N];
        for (int j = i + 1; j < N; ++j) v -= A[i][j] * c[j];
        c[i] = v / A[i][i];
    }
}

// One fitted engine and stage: s v i, the measured us and the fit's, per point.
struct Series {
    std::string name;
    std::vector<double> x, t, f;
};
using Coefficients = std::map<std::string, std::array<double, 4>>;

// The three sweeps through (s, v, i) = (100, 8, 8), and v at i = 1.
std::vector<Point> sweep_points() {
    std::vector<Point> pts;
    for (int s : {25, 50, 100, 200, 400}) pts.push_back({s, 8, 8});
    for (int v : {4, 16, 32}) pts.push_back({100, v, 8});
    for (int i : {1, 2, 4, 16, 32}) pts.push_back({100, 8, i});
    for (int v : {4, 16, 32}) pts.push_back({100, v, 1});  // vertices alone: an edge is its end
    return pts;
}

void register_benchmarks(const std::vector<Point>& pts) {
    for (const char* e : {"fixed", "double"})
        for (const char* stage : {"geometry", "draw"})
            for (Point p : pts) {
                const bool raster = std::strcmp(stage, "draw") == 0;
                auto* b = std::strcmp(e, "fixed") == 0
                              ? benchmark::RegisterBenchmark(key(e, stage, p).c_str(), [=](benchmark::State& s) { run<fx::fixed>(s, p, raster); })
                              : benchmark::RegisterBenchmark(key(e, stage, p).c_str(), [=](benchmark::State& s) { run<double>(s, p, raster); });
                b->Unit(benchmark::kMicrosecond);
            }
}

// The fit per engine and stage, printed as a table; coef receives each one's coefficients.
std::vector<Series> print_fits(const std::vector<Point>& pts, Coefficients& coef) {
    std::printf("\nfit: us = c0 + c_b * s + c_vx * (s v) + c_pt * (s v i)   (ns per body, per vertex, per tessellated "
                "point; a vertex is also one of its edge's i points, so one more vertex at level 1 costs c_vx + c_pt)\n\n");
    std::printf("| engine | stage | c0 us | ns per body | ns per vertex | ns per point | ns per vertex at level 1 | max |residual| |\n"
                "|---|---|---:|---:|---:|---:|---:|---:|\n");
    std::vector<Series> series;
    for (const char* e : {"fixed", "double"})
        for (const char* stage : {"geometry", "draw"}) {
            std::vector<std::array<double, 4>> x;
            std::vector<double> svi, t;
            for (Point p : pts) {
                auto it = g_us.find(key(e, stage, p));
                if (it == g_us.end()) continue;
                const double sv = static_cast<double>(p.s) * p.v;
                x.push_back({1.0, static_cast<double>(p.s), sv, sv * p.i});
                svi.push_back(sv * p.i), t.push_back(it->second);
            }
            if (t.size() < 6) continue;
            double c[4];
            fit<4>(x, t, c);
            double worst = 0;
            Series sr{std::string(e) + " " + stage, svi, t, {}};
            for (std::size_t k = 0; k < t.size(); ++k) {
                const double f = c[0] + c[1] * x[k][1] + c[2] * x[k][2] + c[3] * x[k][3];
                sr.f.push_back(f);
                worst = std::fmax(worst, std::fabs(t[k] - f) / t[k]);
            }
            series.push_back(sr);
            coef[std::string(e) + " " + stage] = {c[0], c[1], c[2], c[3]};
            std::printf("| %s | %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.0f%% |\n", e, stage, c[0], c[1] * 1000, c[2] * 1000,
                        c[3] * 1000, (c[2] + c[3]) * 1000, worst * 100);
        }
    return series;
}

// The double / fixed ratios of the fits, and one more vertex at level 1 straight from the v
// sweep at i = 1 (the slope of us over s v, least squares): the same quantity as the fit's
// c_vx + c_pt, from those four runs alone.
void print_ratios(const std::vector<Point>& pts, const Coefficients& coef) {
    std::map<std::string, double> level1;
    for (const char* e : {"fixed", "double"})
        for (const char* stage : {"geometry", "draw"}) {
            std::vector<std::array<double, 2>> x;
            std::vector<double> t;
            for (Point p : pts) {
                auto it = g_us.find(key(e, stage, p));
                if (p.i != 1 || p.s != 100 || it == g_us.end()) continue;
                x.push_back({1.0, static_cast<double>(p.s) * p.v}), t.push_back(it->second);
            }
            if (t.size() < 3) continue;
            double c[2];
            fit<2>(x, t, c);
            level1[std::string(e) + " " + stage] = c[1] * 1000;
        }
    for (const char* stage : {"geometry", "draw"}) {
        const std::string fk = std::string("fixed ") + stage, dk = std::string("double ") + stage;
        std::printf("\n%s, double / fixed:", stage);
        if (coef.count(fk) && coef.count(dk)) {
            const auto &cf = coef.at(fk), &cd = coef.at(dk);
            std::printf(" %.2f per body, %.2f per tessellated point, %.2f per vertex at level 1;", cd[1] / cf[1], cd[3] / cf[3],
                        (cd[2] + cd[3]) / (cf[2] + cf[3]));
        }
        if (level1.count(fk) && level1.count(dk))
            std::printf(" per vertex at level 1 from the i = 1 runs alone: %.1f ns fixed, %.1f double, %.2f", level1[fk],
                        level1[dk], level1[dk] / level1[fk]);
    }
    std::printf("\n");
}

// Every point's time against the fits.
void print_points(const std::vector<Point>& pts, const std::vector<Series>& series) {
    std::printf("\n| s | v | i | s v i |");
    for (const Series& sr : series) std::printf(" %s us (fit) |", sr.name.c_str());
    std::printf("\n|---:|---:|---:|---:|");
    for (std::size_t k = 0; k < series.size(); ++k) std::printf("---:|");
    std::printf("\n");
    for (std::size_t k = 0; k < pts.size(); ++k) {
        std::printf("| %d | %d | %d | %d |", pts[k].s, pts[k].v, pts[k].i, pts[k].s * pts[k].v * pts[k].i);
        for (const Series& sr : series)
            if (k < sr.t.size()) std::printf(" %.0f (%.0f) |", sr.t[k], sr.f[k]);
        std::printf("\n");
    }
}

// The series as an SVG plot of us against s v i; false if the file cannot be written.
bool write_svg(const std::string& svg, const std::vector<Series>& series) {
    FILE* out = std::fopen(svg.c_str(), "w");
    if (!out) {
        std::fprintf(stderr, "bench_scaling: cannot write %s\n", svg.c_str());
        return false;
    }
    double xmax = 0, tmax = 0;
    for (const Series& sr : series)
        for (std::size_t k = 0; k < sr.t.size(); ++k) xmax = std::fmax(xmax, sr.x[k]), tmax = std::fmax(tmax, sr.t[k]);
    const double W = 640, H = 400, L = 60, B = 40;
    auto X = [&](double x) { return L + (W - L - 20) * x / xmax; };
    auto Y = [&](double t) { return H - B - (H - B - 20) * t / tmax; };
    std::fprintf(out, "<svg xmlns='http://www.w3.org/2000/svg' width='%g' height='%g' font-family='sans-serif' font-size='11'>\n", W, H);
    std::fprintf(out, "<rect width='100%%' height='100%%' fill='white'/>\n<line x1='%g' y1='%g' x2='%g' y2='%g' stroke='black'/>\n", L, H - B, W - 20, H - B);
    std::fprintf(out, "<line x1='%g' y1='%g' x2='%g' y2='20' stroke='black'/>\n", L, H - B, L);
    std::fprintf(out, "<text x='%g' y='%g' text-anchor='middle'>tessellated points s v i (max %.0f)</text>\n", (L + W) / 2, H - 10, xmax);
    std::fprintf(out, "<text x='12' y='%g' transform='rotate(-90 12 %g)' text-anchor='middle'>us per frame (max %.0f)</text>\n", H / 2, H / 2, tmax);
    const char* colors[] = {"#c03030", "#e08030", "#3050c0", "#30a0c0"};
    for (std::size_t k = 0; k < series.size(); ++k) {
        const Series& sr = series[k];
        for (std::size_t j = 0; j < sr.t.size(); ++j)
            std::fprintf(out, "<circle cx='%.1f' cy='%.1f' r='3' fill='%s'/>\n", X(sr.x[j]), Y(sr.t[j]), colors[k % 4]);
        std::fprintf(out, "<text x='%g' y='%g' fill='%s'>%s</text>\n", L + 10, 30 + 14.0 * static_cast<double>(k), colors[k % 4], sr.name.c_str());
    }
    std::fprintf(out, "</svg>\n");
    std::fclose(out);
    std::printf("\nplot: %s\n", svg.c_str());
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    std::string svg;
    for (int k = 1; k < argc; ++k)
        if (std::strncmp(argv[k], "--svg=", 6) == 0) svg = argv[k] + 6;
    benchmark::Initialize(&argc, argv);
    const std::vector<Point> pts = sweep_points();
    register_benchmarks(pts);
    FastestReporter rep([](const std::string& name, const benchmark::BenchmarkReporter::Run& r) {
        keep_fastest(g_us, name, r.GetAdjustedCPUTime());
    });
    benchmark::RunSpecifiedBenchmarks(&rep);
    Coefficients coef;
    const std::vector<Series> series = print_fits(pts, coef);
    print_ratios(pts, coef);
    print_points(pts, series);
    if (!svg.empty() && !series.empty() && !write_svg(svg, series)) return 1;
    return 0;
}
