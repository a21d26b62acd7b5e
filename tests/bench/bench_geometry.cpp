// Geometry cost of the same scenes through the fixed, float and double engines, side by side
// in one run (Google Benchmark), per vertex and per tessellated point:
//     build/release/bench_geometry
//
//   vertices/<engine>/<scene>  every body's vertices from its centre and facing, in polar
//                              (walk_end, what `dump` exports): ns per vertex (counter ns_per_item)
//   vectors/<engine>/<scene>   the same vertices as the draw makes them: one matrix per body
//                              (geo::body_motion) applied to the cached local 3-vectors
//                              (geo::MotionApply): ns per vertex, the motion included
//   motion/<engine>/<scene>    the matrix alone (geo::body_motion): ns per body
//   apply/<engine>/<scene>     its nine products alone (geo::MotionApply, matrices made once):
//                              ns per vertex
//   points/<engine>/<scene>    every edge tessellated at its body's level (edge_points): ns per
//                              point produced, polar (r, theta)
//   screen/<engine>/<scene>    the draw's whole geometry: vertices, edge points, projection and
//                              screen coordinates (SubPoints for the rasteriser): ns per point
// The scenes are the kiosk (grids and five bodies, K = 0 at start, moved to K = -0.6 here so that
// every curvature function does real work) and stress (200 bodies of 8 vertices at level 8,
// K = -1), each stepped 30 frames first. A summary table of double/fixed and float/fixed ratios
// follows the benchmark output.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "render/draw_world.hpp"
#include "fastest.hpp"

namespace {

using namespace noneuclid;

template <class T>
world::World<T> make_world(const char* scene_name) {
    world::Scene scene;
    world::builtin_scene(scene_name, {}, scene);
    if (std::string(scene_name) == "kiosk") scene.curvature = -0.6;
    world::World<T> w(scene);
    for (int i = 0; i < 30; ++i) w.step(1.0 / 60);
    return w;
}

std::map<std::string, double> g_ns;  // name -> ns per item, for the summary

template <class T>
void record(benchmark::State& st, const std::string& name, double items_per_iter) {
    st.counters["ns_per_item"] = benchmark::Counter(items_per_iter, benchmark::Counter::kIsIterationInvariantRate |
                                                                        benchmark::Counter::kInvert);
    st.counters["items"] = items_per_iter;
    (void)name;
}

template <class T>
void vertices(benchmark::State& st, const char* scene) {
    const world::World<T> w = make_world<T>(scene);
    std::vector<geo::Polar<T>> buf(4096);
    double n = 0;
    for (const auto& b : w.bodies) n += static_cast<double>(b.local.size());
    for (auto _ : st) {
        for (const auto& b : w.bodies) w.vertices(b, buf.data());
        benchmark::DoNotOptimize(buf.data());
        benchmark::ClobberMemory();
    }
    record<T>(st, "vertices", n);
}

// The bodies' shape caches, made and refreshed for the world's K.
template <class T>
std::vector<geo::ShapeCache<T>> shapes_of(const world::World<T>& w) {
    std::vector<geo::ShapeCache<T>> caches;
    render::make_shape_caches(w, caches);
    for (std::size_t i = 0; i < caches.size(); ++i) caches[i].refresh(w.K, w.bodies[i]);
    return caches;
}

// The draw's vertices: the body's motion, applied to its cached local 3-vectors
// (geo::ShapeCache) as body_screen_points applies it (geo::MotionApply).
template <class T>
void vectors(benchmark::State& st, const char* scene) {
    const world::World<T> w = make_world<T>(scene);
    std::vector<geo::ShapeCache<T>> shapes = shapes_of(w);
    std::vector<geo::Vec3<T>> buf(4096);
    double n = 0;
    for (const auto& b : w.bodies) n += static_cast<double>(b.local.size());
    for (auto _ : st) {
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
            const auto& b = w.bodies[i];
            const geo::ShapeCache<T>& sh = shapes[i].refresh(w.K, b);
            const geo::Motion<T> m = geo::body_motion(w.K, b.centre, b.facing);
            const geo::MotionApply<T> apply(m);
            apply(sh.local.data(), buf.data(), b.local.size());
            benchmark::DoNotOptimize(buf.data());
        }
        benchmark::ClobberMemory();
    }
    record<T>(st, "vectors", n);
}

// The two halves of `vectors`: each body's matrix, and the matrices applied to the vertices.
template <class T>
void motion(benchmark::State& st, const char* scene) {
    const world::World<T> w = make_world<T>(scene);
    std::vector<geo::Motion<T>> buf(w.bodies.size());
    for (auto _ : st) {
        for (std::size_t i = 0; i < w.bodies.size(); ++i)
            buf[i] = geo::body_motion(w.K, w.bodies[i].centre, w.bodies[i].facing);
        benchmark::DoNotOptimize(buf.data());
        benchmark::ClobberMemory();
    }
    record<T>(st, "motion", static_cast<double>(w.bodies.size()));
}
template <class T>
void apply(benchmark::State& st, const char* scene) {
    const world::World<T> w = make_world<T>(scene);
    const std::vector<geo::ShapeCache<T>> shapes = shapes_of(w);
    std::vector<geo::Motion<T>> ms;
    for (const auto& b : w.bodies) ms.push_back(geo::body_motion(w.K, b.centre, b.facing));
    std::vector<geo::Vec3<T>> buf(4096);
    double n = 0;
    for (const auto& b : w.bodies) n += static_cast<double>(b.local.size());
    for (auto _ : st) {
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
            const geo::MotionApply<T> a(ms[i]);
            a(shapes[i].local.data(), buf.data(), w.bodies[i].local.size());
            benchmark::DoNotOptimize(buf.data());
        }
        benchmark::ClobberMemory();
    }
    record<T>(st, "apply", n);
}

template <class T>
void points(benchmark::State& st, const char* scene) {
    const world::World<T> w = make_world<T>(scene);
    // The vertices, once: this measures the tessellation alone.
    std::vector<std::vector<geo::Polar<T>>> verts;
    double n = 0;
    for (const auto& b : w.bodies) {
        verts.emplace_back(b.local.size());
        w.vertices(b, verts.back().data());
        const std::size_t edges = b.local.size() < 2 ? 0 : (b.desc->closed ? b.local.size() : b.local.size() - 1);
        n += static_cast<double>(edges) * (b.desc->tessellation + 1);
    }
    for (auto _ : st) {
        T acc{};
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
            const auto& b = w.bodies[i];
            const auto& v = verts[i];
            const std::size_t m = v.size();
            const std::size_t edges = m < 2 ? 0 : (b.desc->closed ? m : m - 1);
            for (std::size_t e = 0; e < edges; ++e)
                geo::edge_points(w.K, v[e], v[(e + 1) % m], b.desc->tessellation,
                                 [&](int, geo::Polar<T> p) { acc = acc + p.r + p.theta; });
        }
        benchmark::DoNotOptimize(acc);
    }
    record<T>(st, "points", n);
}

template <class T>
void screen(benchmark::State& st, const char* scene) {
    const world::World<T> w = make_world<T>(scene);
    render::DrawScratch<T> s;
    s.prepare(w);
    const render::DrawOptions o;
    const render::ScreenMap<T> m = render::ScreenMap<T>::of(800, 480, w.K, w.R, o.projection);
    double n = 0;
    for (auto _ : st) {
        std::size_t total = 0;
        for (std::size_t i = 0; i < w.bodies.size(); ++i)
            total += render::body_screen_points(w, w.bodies[i], s.shapes[i], m, o, s.vertices.data(), s.vectors.data(), s.points.data());
        benchmark::DoNotOptimize(s.points.data());
        benchmark::ClobberMemory();
        n = static_cast<double>(total);
    }
    record<T>(st, "screen", n);
}

template <class T>
const char* engine_name() {
    if constexpr (std::is_same_v<T, fx::fixed>) return "fixed";
    else if constexpr (std::is_same_v<T, float>) return "float";
    else return "double";
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    const char* scenes[] = {"kiosk", "stress"};
    for (const char* sc : scenes) {
        auto reg = [&](auto tag) {
            using T = decltype(tag);
            const std::string e = engine_name<T>();
            benchmark::RegisterBenchmark(("vertices/" + e + "/" + sc).c_str(), [sc](benchmark::State& s) { vertices<T>(s, sc); });
            benchmark::RegisterBenchmark(("vectors/" + e + "/" + sc).c_str(), [sc](benchmark::State& s) { vectors<T>(s, sc); });
            benchmark::RegisterBenchmark(("motion/" + e + "/" + sc).c_str(), [sc](benchmark::State& s) { motion<T>(s, sc); });
            benchmark::RegisterBenchmark(("apply/" + e + "/" + sc).c_str(), [sc](benchmark::State& s) { apply<T>(s, sc); });
            benchmark::RegisterBenchmark(("points/" + e + "/" + sc).c_str(), [sc](benchmark::State& s) { points<T>(s, sc); });
            benchmark::RegisterBenchmark(("screen/" + e + "/" + sc).c_str(), [sc](benchmark::State& s) { screen<T>(s, sc); });
        };
        reg(fx::fixed{});
        reg(float{});
        reg(double{});
    }
    FastestReporter rep([](const std::string& name, const benchmark::BenchmarkReporter::Run& r) {
        auto it = r.counters.find("ns_per_item");
        if (it != r.counters.end()) keep_fastest(g_ns, name, it->second.value * 1e9);
    });
    benchmark::RunSpecifiedBenchmarks(&rep);
    std::printf("\nns per item (vertex, body or point); ratio > 1: fixed is faster\n\n");
    std::printf("| stage | scene | fixed ns | float ns | double ns | double/fixed | float/fixed |\n|---|---|---:|---:|---:|---:|---:|\n");
    for (const char* stage : {"vertices", "vectors", "motion", "apply", "points", "screen"})
        for (const char* sc : scenes) {
            auto get = [&](const char* e) {
                auto it = g_ns.find(std::string(stage) + "/" + e + "/" + sc);
                return it == g_ns.end() ? 0.0 : it->second;
            };
            const double f = get("fixed"), fl = get("float"), d = get("double");
            if (f <= 0) continue;
            std::printf("| %s | %s | %.1f | %.1f | %.1f | %.2f | %.2f |\n", stage, sc, f, fl, d, d / f, fl / f);
        }
    return 0;
}
