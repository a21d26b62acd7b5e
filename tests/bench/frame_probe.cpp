// Runs frames (or one stage of a frame) N times for instruction counting under qemu-user
// (tests/bench/arm-frame-insncount.sh runs the counter and does the arithmetic):
//     frame_probe STAGE ENGINE SCENE WxH FORMAT N [THREADS [K [TESSELLATION [VERTICES]]]]
// STAGE: frame (world step + draw_world + copy to a second buffer, what the kiosk does per
// frame, HUD aside), step, backdrop, geometry (every body's screen points), raster (the bodies'
// lines from points computed once), copy (render::copy_canvas), memcpy (the same bytes), fill
// (the filled and textured bodies' fills alone), fillmemset (a memset of as many pixels as the
// fills cover).
// ENGINE fixed|double|float, SCENE kiosk|stress|textured|... (NAME+instruments: with four instruments measured in it; earth:KM: the earth zoomed to KM km; filled: textured with colours for
// textures) or game:A:B (the asteroids scene in play
// with A asteroids and B bullets in flight; stage collide: the game's collision tests alone,
// the broad and narrow phases as world/game.hpp runs them), FORMAT rgb565|xrgb8888|rgb888; K sets the
// curvature (the kiosk starts flat, where the double engine's series are at their cheapest);
// K = sweep changes it every frame as attract mode does, from -0.6 (sweep@K0: from K0), so every
// body's shape cache (geo::ShapeCache) is rebuilt every frame: the worst case of the frame
// stage. K = zoom: curvature down held from the start, so that a scene that zooms (the earth)
// zooms in every frame (its vertices rescaled, its shape caches rebuilt).
// The cost of one is (count at N - count at 0) / N: the run at N = 0 does the same set-up and
// the same one warm-up frame.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "render/blit.hpp"
#include "render/draw_world.hpp"
#include "render/parallel_frame.hpp"
#include "world/game.hpp"

namespace {

using namespace noneuclid;

// The asteroids scene set for `asteroids` large asteroids at once and a shot every 0.1 s (16 in
// flight over a bullet's 1.6 s), the ship safe throughout, so that a few frames keep the counts.
bool game_scene(const char* name, world::Scene& scene, int& bullets) {
    int asteroids = 0;
    if (std::sscanf(name, "game:%d:%d", &asteroids, &bullets) != 2 || asteroids < 1 || bullets < 1) return false;
    if (!world::builtin_scene("asteroids", {}, scene)) return false;
    scene.bodies.erase(std::remove_if(scene.bodies.begin(), scene.bodies.end(),
                                      [](const world::SceneBody& b) { return b.role != world::BodyKind::body && !b.grid && !b.controlled; }),
                       scene.bodies.end());
    world::GameSettings& g = scene.game;
    g.asteroids = g.asteroids_max = asteroids;
    g.bullets = bullets;
    g.bullet_cooldown = g.bullet_range / g.bullet_speed / bullets;
    g.invulnerable = 1e6;
    g.levels.clear();  // K stays the scene's (or what K= sets)
    std::string why;
    return world::add_game_slots(scene, why);
}

// The game's collision tests on the world as it is (world/game.hpp's broad and narrow phases,
// with the same functions), without changing it: every bullet against every asteroid, the ship
// against every asteroid. Returns how many narrow tests found a contact.
template <class W>
long collide(const W& w, typename W::scalar dt) {
    using T = typename W::scalar;
    geo::Vec3<T> av[world::kGameMaxVertices], ac, sv[world::kGameMaxVertices], sc;
    long found = 0;
    const world::Body<T>* ship = nullptr;
    for (const auto& b : w.bodies)
        if (b.active && b.desc->controlled) ship = &b;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const auto& a = w.bodies[i];
        if (!a.active || a.desc->kind() != world::BodyKind::asteroid) continue;
        T radius{};
        for (const auto& v : a.local) radius = v.r > radius ? v.r : radius;
        bool have = false;
        auto vectors = [&] {
            if (!have) geo::body_vectors(w.K, a.centre, a.facing, a.local.data(), a.local.size(), ac, av), have = true;
        };
        for (const auto& u : w.bodies) {
            if (!u.active || u.desc->kind() != world::BodyKind::bullet) continue;
            if (geo::distance(w.K, u.centre, a.centre) > radius + u.speed * dt) continue;
            vectors();
            const geo::Vec3<T> q = geo::to_vec(w.K, u.centre);
            found += geo::segment_meets_star(ac, av, a.local.size(), q, q);
        }
        if (ship && geo::distance(w.K, ship->centre, a.centre) <= radius + T(0.12)) {
            vectors();
            geo::body_vectors(w.K, ship->centre, ship->facing, ship->local.data(), ship->local.size(), sc, sv);
            found += geo::polygons_overlap(ac, av, a.local.size(), sc, sv, ship->local.size());
        }
    }
    return found;
}

template <class T>
int run(const std::string& stage, const char* scene_name, int w, int h, render::PixelFormat f, long n, int threads,
        const char* K, int tess, int verts) {
    world::Scene scene;
    world::SceneParams params;
    if (tess > 0) params.tessellation = tess;  // stress only
    if (verts > 0) params.vertices = verts;    // stress only
    int bullets = 0;
    const bool game = std::strncmp(scene_name, "game:", 5) == 0;
    // "filled": the textured scene with each texture replaced by a colour (the fill's spans alone).
    const bool filled = std::strcmp(scene_name, "filled") == 0;
    // "NAME+instruments": the scene with a triangle, a circle, the parallels and a ring of seven
    // triangles measured in it (world/instruments.hpp): the instruments' cost is the difference.
    std::string name = filled ? "textured" : scene_name;
    // "earth:KM": the earth scene zoomed to KM kilometres (--view).
    if (name.rfind("earth:", 0) == 0) params.view_km = std::atof(name.c_str() + 6), name = "earth";
    const std::size_t plus = name.find("+instruments");
    const bool instruments = plus != std::string::npos;
    if (instruments) name.resize(plus);
    if (game ? !game_scene(scene_name, scene, bullets) : !world::builtin_scene(name, params, scene)) {
        std::fprintf(stderr, "frame_probe: no built-in scene '%s'.\n", scene_name);
        return 2;
    }
    if (instruments) {
        world::MeasureDecl t, c, p, q;
        t.kind = geo::Instrument::triangle, t.marks = {{1.2, 90}, {1.2, 210}, {1.2, 330}};
        c.kind = geo::Instrument::circle, c.marks = {{0.6, 200}}, c.radius = 0.9;
        p.kind = geo::Instrument::parallels, p.marks = {{1.1, 10}, {1.4, 60}}, p.length = 1.2;
        q.kind = geo::Instrument::polygon;
        scene.measures = {t, c, p, q};
    }
    if (K && std::string(K).rfind("sweep", 0) == 0) {  // attract mode's sweep: K changes every frame (-1 to 1 in 40 s)
        scene.curvature = std::string(K).size() > 6 ? std::atof(K + 6) : -0.6;  // sweep@K0 starts at K0
        scene.sweep_rate = 0.05;
    } else if (K && *K && std::strcmp(K, "zoom") != 0) {
        scene.curvature = std::atof(K);
    }
    if (filled)
        for (world::SceneBody& b : scene.bodies)
            if (b.texture) b.texture = nullptr, b.filled = true, b.fill = {200, 120, 60};
    world::World<T> wd(scene);
    if (K && std::strcmp(K, "zoom") == 0) wd.press(world::Action::curvature_down);
    if (game) {  // in play: fire held, turning, until the bullets are all in flight
        wd.press(world::Action::fire);
        wd.press(world::Action::left);
        for (int i = 0; i < 60 * 2; ++i) wd.step(1.0 / 60);
        // Hits split asteroids: as many as asked for, the first ones kept.
        int kept = 0, flying = 0;
        for (auto& b : wd.bodies) {
            if (b.active && b.desc->kind() == world::BodyKind::asteroid && ++kept > scene.game.asteroids)
                b.active = false, --kept;
            flying += b.active && b.desc->kind() == world::BodyKind::bullet;
        }
        std::fprintf(stderr, "frame_probe: %d asteroids, %d bullets in flight\n", kept, flying);
    }
    render::DrawScratch<T> scratch;
    scratch.prepare(wd);
    render::WorkerPool pool(threads);
    render::ParallelScratch<T> par;
    par.prepare(wd, pool);
    const std::size_t bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(f.bytes_per_pixel());
    std::vector<uint8_t> back(bytes), front(bytes);
    const render::Canvas c(back.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    const render::Canvas fb(front.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    const render::DrawOptions o;
    const double dt = 1.0 / 60;
    auto frame = [&] {
        wd.step(dt);
        if (threads > 1)
            render::draw_world(c, wd, o, par, pool);
        else
            render::draw_world(c, wd, o, scratch);
        render::copy_canvas(c, fb);
    };
    frame();  // warm-up, in every run
    auto m = render::ScreenMap<T>::of(c, wd.K, wd.R, o.projection);
    if (scratch.any_detail) render::set_detail(m, scratch.detail, wd.K, wd.R, o.projection);  // (as the frame draws them)
    std::vector<render::SubPoint> pts;
    std::vector<std::size_t> counts;
    for (std::size_t i = 0; i < wd.bodies.size(); ++i) {
        const auto& b = wd.bodies[i];
        if (!render::body_shown(b, o)) {  // (a game's spare slots)
            counts.push_back(0);
            continue;
        }
        std::vector<render::SubPoint> p(render::body_point_capacity(wd, b));
        const std::size_t k =
            render::body_screen_points(wd, b, scratch.shapes[i], m, o, scratch.vertices.data(), scratch.vectors.data(), p.data());
        pts.insert(pts.end(), p.begin(), p.begin() + static_cast<std::ptrdiff_t>(k));
        counts.push_back(k);
    }
    // The fills alone (render/fill.hpp: each body's plan and rows), and the pixels they cover:
    // drawn once on a cleared canvas and counted, for the memset of as many pixels.
    auto fills = [&] {
        scratch.fill.begin_frame(c);
        for (std::size_t b = 0; b < wd.bodies.size(); ++b)
            if (render::body_shown(wd.bodies[b], o))
                if (const render::FillJob* j = scratch.fill.plan(wd, b, m, o, w, h))
                    render::fill_rows(c, *j, 0, h, scratch.fill.work[0]);
    };
    std::fill(back.begin(), back.end(), 0);
    fills();
    std::size_t covered = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) covered += c.get_word(x, y) != 0;
    std::fprintf(stderr, "frame_probe: the fills cover %zu pixels\n", covered);
    uint64_t check = 0;
    for (long i = 0; i < n; ++i) {
        if (stage == "frame") frame();
        else if (stage == "step") wd.step(dt);
        else if (stage == "backdrop") render::draw_backdrop(c, m, o);
        else if (stage == "geometry") {
            for (std::size_t b = 0; b < wd.bodies.size(); ++b)
                if (render::body_shown(wd.bodies[b], o))
                    check += render::body_screen_points(wd, wd.bodies[b], scratch.shapes[b], m, o, scratch.vertices.data(),
                                                    scratch.vectors.data(), scratch.points.data());
        } else if (stage == "raster") {
            std::size_t at = 0;
            for (std::size_t k = 0; k < wd.bodies.size(); ++k) {
                render::draw_screen_points(c, pts.data() + at, counts[k], render::body_color(wd.bodies[k], o), {});
                at += counts[k];
            }
        } else if (stage == "copy") render::copy_canvas(c, fb);
        else if (stage == "memcpy") std::memcpy(front.data(), back.data(), bytes);
        else if (stage == "collide") check += static_cast<uint64_t>(collide(wd, T(dt)));
        else if (stage == "fill") fills();
        else if (stage == "fillmemset") std::memset(back.data(), static_cast<int>(i & 255), covered * static_cast<std::size_t>(f.bytes_per_pixel()));
        else {
            std::fprintf(stderr, "frame_probe: unknown stage '%s'.\n", stage.c_str());
            return 2;
        }
        check += front[i % bytes] + back[(i * 7) % bytes];
    }
    std::printf("%s %s %ld checksum %llu\n", stage.c_str(), scene_name, n, static_cast<unsigned long long>(check));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 7) {
        std::fprintf(stderr, "usage: frame_probe frame|step|backdrop|geometry|raster|copy|memcpy|collide|fill|fillmemset fixed|double|float SCENE|game:A:B WxH rgb565|xrgb8888|rgb888 N [THREADS [K [TESSELLATION [VERTICES]]]]\n");
        return 2;
    }
    int w = 0, h = 0;
    if (std::sscanf(argv[4], "%dx%d", &w, &h) != 2 || w <= 0 || h <= 0) {
        std::fprintf(stderr, "frame_probe: size must be WxH, not '%s'.\n", argv[4]);
        return 2;
    }
    const std::string fs = argv[5];
    const render::PixelFormat f = fs == "rgb565" ? render::PixelFormat::rgb565()
                                  : fs == "rgb888" ? render::PixelFormat::rgb888()
                                                   : render::PixelFormat::xrgb8888();
    const long n = std::atol(argv[6]);
    const int threads = argc > 7 ? std::atoi(argv[7]) : 1;
    const char* K = argc > 8 ? argv[8] : nullptr;
    const int tess = argc > 9 ? std::atoi(argv[9]) : 0;
    const int verts = argc > 10 ? std::atoi(argv[10]) : 0;
    const std::string e = argv[2];
    if (e == "fixed") return run<fx::fixed>(argv[1], argv[3], w, h, f, n, threads, K, tess, verts);
    if (e == "double") return run<double>(argv[1], argv[3], w, h, f, n, threads, K, tess, verts);
    if (e == "float") return run<float>(argv[1], argv[3], w, h, f, n, threads, K, tess, verts);
    std::fprintf(stderr, "frame_probe: engine must be fixed, double or float, not '%s'.\n", argv[2]);
    return 2;
}
