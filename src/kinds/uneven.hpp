// The uneven world (uneven/world.hpp, docs/uneven.md) as a kind (kinds/kind.hpp): double only,
// drawn by uneven::Drawing on one thread in its two views (the chart, and the inhabitant's view
// for every other projection), its HUD note the bumps' gain, dumped by uneven/dump.hpp.
#pragma once

#include <cstdio>

#include "kinds/constant.hpp"
#include "kinds/kind.hpp"
#include "uneven/draw.hpp"
#include "uneven/dump.hpp"

namespace noneuclid::kinds {

class Uneven {
public:
    using World = uneven::World;

    explicit Uneven(const world::Scene& scene) : world(scene) {}

    uneven::World world;

    void prepare(const render::WorkerPool&) { drawing_.prepare(world); }
    void draw(const render::Canvas& c, const render::DrawOptions& o, bool backdrop, render::WorkerPool&) {
        drawing_.draw(c, world, o, backdrop);
    }

    // Its two views, in turn: the chart (the stereographic projection) and the inhabitant's.
    static geo::Projection next_view(geo::Projection p) {
        return uneven::is_chart_view(p) ? geo::Projection::azimuthal_equidistant : geo::Projection::stereographic;
    }
    static const char* view_words(geo::Projection p, lang::Language l) {
        return lang::text(uneven::is_chart_view(p) ? lang::Text::view_chart : lang::Text::view_inhabitant, l);
    }
    static bool marks_in(geo::Projection p) { return uneven::is_chart_view(p); }  // (a tap marks the chart)

    bool note(char* out, std::size_t size, lang::Language l) const {  // the bumps' gain
        std::snprintf(out, size, lang::text(lang::Text::bump_gain, l), world.gain());
        return true;
    }

    // The keys: P its two views, < > its bumps; the buttons as in the world of constant K.
    static lang::Text legend(bool keys, const world::Scene& s) {
        if (!keys) return constant_legend(keys, s);
        return s.game.on ? lang::Text::legend_uneven_game_keys : lang::Text::legend_uneven_keys;
    }

    static bool ship_speed(const World& w, double& speed) { return plane_ship_speed(w, speed); }
    static bool aim(const World& w, double& turn, double& distance) { return plane_aim(w, turn, distance); }
    static bool has_instrument(const World&) { return true; }

    void dump(const files::DumpOptions& o, std::string& line) const { files::dump_frame(world, o, line); }

private:
    uneven::Drawing drawing_;
};

}  // namespace noneuclid::kinds
