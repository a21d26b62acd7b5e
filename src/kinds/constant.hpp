// The world of constant curvature K (world/world.hpp) as a kind (kinds/kind.hpp), on engine W's
// scalar and formulas: drawn by render/draw_world.hpp on one thread or by
// render/parallel_frame.hpp over a pool (the same pixels), in every projection; its HUD note is
// the earth scene's zoom; dumped by files/dump.hpp.
#pragma once

#include <cmath>
#include <cstdio>

#include "kinds/kind.hpp"
#include "render/draw_world.hpp"
#include "render/hud.hpp"
#include "render/parallel_frame.hpp"
#include "render/play.hpp"
#include "world/earth.hpp"

namespace noneuclid::kinds {

// The HUD's controls line of a world of constant K, for keys or the kiosk's buttons (the
// kiosk's fire button does something only in the game or with a scene's instruments).
inline lang::Text constant_legend(bool keys, const world::Scene& s) {
    using lang::Text;
    const bool fire = s.game.on || !s.measures.empty();
    return s.zoom.on() ? (keys ? Text::legend_zoom_keys : Text::legend_zoom_buttons)
                       : (keys ? Text::legend_keys : fire ? Text::legend_buttons : Text::legend_buttons_no_fire);
}

template <class W>
class Constant {
public:
    using World = W;
    using T = typename W::scalar;

    explicit Constant(const world::Scene& scene) : world(scene) {}

    W world;

    void prepare(const render::WorkerPool& pool) {
        one_.prepare(world);
        if (pool.size() > 1) parallel_.prepare(world, pool);
    }
    // For one thread without a pool (the firmware), keep_still false keeping no room for still
    // bodies' points (its RAM is short); the buffers, to reserve more.
    render::DrawScratch<T, typename W::engine>& prepare_one_thread(bool keep_still) {
        one_.prepare(world, keep_still);
        return one_;
    }
    void draw(const render::Canvas& c, const render::DrawOptions& o, bool backdrop, render::WorkerPool& pool) {
        if (pool.size() > 1)
            render::draw_world(c, world, o, parallel_, pool, backdrop);
        else
            render::draw_world(c, world, o, one_, backdrop);
    }
    // For a caller with no pool (the firmware, the C interface): one thread.
    void draw(const render::Canvas& c, const render::DrawOptions& o, bool backdrop = true) {
        render::draw_world(c, world, o, one_, backdrop);
    }

    static geo::Projection next_view(geo::Projection p) { return render::next_projection(p); }
    static const char* view_words(geo::Projection p, lang::Language l) { return render::projection_words(p, l); }
    static bool marks_in(geo::Projection) { return true; }

    // The zoom's line (the earth scene): the screen's radius in km, and where the zoom ends, that
    // it ends there (docs/earth.md).
    bool note(char* out, std::size_t size, lang::Language l) const {
        const auto z = world.zoom();
        if (!z.on) return false;
        const double km = 3.14159265358979323846 * world::kEarthRadiusKm * std::sqrt(z.z);
        using lang::Text;
        std::snprintf(out, size, lang::text(z.least ? Text::view_km_least : z.most ? Text::view_km_most : Text::view_km, l),
                      km);
        return true;
    }

    static lang::Text legend(bool keys, const world::Scene& s) { return constant_legend(keys, s); }

    static bool ship_speed(const World& w, double& speed) { return plane_ship_speed(w, speed); }
    static bool aim(const World& w, double& turn, double& distance) { return plane_aim(w, turn, distance); }
    static bool has_instrument(const World&) { return true; }

    void dump(const files::DumpOptions& o, std::string& line) const { files::dump_frame(world, o, line); }

private:
    render::DrawScratch<T, typename W::engine> one_;
    render::ParallelScratch<T, typename W::engine> parallel_;
};

}  // namespace noneuclid::kinds
