// The three-dimensional world (space/scene_world.hpp, docs/space.md) as a kind (kinds/kind.hpp):
// on the fixed engine (Q16.16, the device's) and the double one, drawn on one thread (space/scene_draw.hpp) in its two views, P switching them —
// the inhabitant's view (the projection setting's azimuthal equidistant, the default) and the
// map (stereographic) — with the buttons and keys of the world of constant K, and dumped as each
// body's distance, direction and facing (docs/file-formats.md).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "kinds/constant.hpp"
#include "kinds/kind.hpp"
#include "space/scene_draw.hpp"

namespace noneuclid::kinds {

template <class T>
class SpaceOn {
public:
    using World = space::SceneWorldOf<T>;

    explicit SpaceOn(const world::Scene& scene) : world(scene) { rows_.reserve(kKeptRows); }

    World world;

    void prepare(const render::WorkerPool&) {}
    void draw(const render::Canvas& c, const render::DrawOptions& o, bool backdrop, render::WorkerPool&) {
        space::draw_space(c, world, o, is_map(o.projection), backdrop, &rows_);
    }

    static bool is_map(geo::Projection p) { return p == geo::Projection::stereographic; }
    static geo::Projection next_view(geo::Projection p) {
        return is_map(p) ? geo::Projection::azimuthal_equidistant : geo::Projection::stereographic;
    }
    static const char* view_words(geo::Projection p, lang::Language l) {
        return lang::text(is_map(p) ? lang::Text::view_map : lang::Text::view_inhabitant, l);
    }
    static bool marks_in(geo::Projection) { return false; }  // (no instruments yet)
    // A honeycomb's fit at the current K: its cubes round an edge close it, or leave this wedge
    // (negative: they overlap); within 0.05 degrees it fits.
    bool note(char* out, std::size_t size, lang::Language l) const {
        const space::Honeycomb& h = world.honeycomb_as_set();
        if (!h.kind) return false;
        space::CubeShape shape;
        const double K = static_cast<double>(world.K);
        if (!space::cube_shape(K, h.kind->edge, shape)) {
            std::snprintf(out, size, lang::text(lang::Text::honeycomb_none, l), h.kind->name, h.closing_K);
            return true;
        }
        const double gap = (2 * 3.14159265358979323846 - h.kind->cells * shape.dihedral) * 180 / 3.14159265358979323846;
        if (std::fabs(gap) < 0.05)
            std::snprintf(out, size, lang::text(lang::Text::honeycomb_fits, l), h.kind->name, h.kind->cells, K);
        else
            std::snprintf(out, size, lang::text(lang::Text::honeycomb_gap, l), h.kind->name, h.kind->cells, gap, h.closing_K);
        return true;
    }
    static lang::Text legend(bool keys, const world::Scene&) {
        return keys ? lang::Text::legend_space_keys : lang::Text::legend_space_buttons;
    }

    // One line (docs/file-formats.md): the frame, the time, K, and each body's kind (ship or
    // body), solid, "r" (its distance from O), "dir" (the unit 3-vector at O toward it), "facing"
    // (its forward, in the frame carried from O) and speed.
    void dump(const files::DumpOptions&, std::string& line) const {
        char buf[256];
        std::snprintf(buf, sizeof buf, "{\"frame\":%ld,\"t\":%.9g,\"K\":%.9g,\"kind\":\"space\",\"bodies\":[", world.frame,
                      world.time, static_cast<double>(world.K));
        line = buf;
        for (std::size_t i = 0; i < world.bodies.size(); ++i) {
            const space::Body<T>& b = world.bodies[i];
            const auto d = [](T v) { return static_cast<double>(v); };
            const space::V3<T>& u = b.at.u;
            const space::V3<T>& f = b.frame.forward;
            std::snprintf(buf, sizeof buf,
                          "%s{\"kind\":\"%s\",\"solid\":\"%s\",\"r\":%.9g,\"dir\":[%.9g,%.9g,%.9g],"
                          "\"facing\":[%.9g,%.9g,%.9g],\"speed\":%.9g}",
                          i ? "," : "", b.ship ? "ship" : "body", world.solid(b).name, d(b.at.r), d(u.x), d(u.y), d(u.z),
                          d(f.x), d(f.y), d(f.z), d(b.speed));
            line += buf;
        }
        line += "]}";
    }

    static bool ship_speed(const World& w, double& speed) {
        speed = static_cast<double>(w.bodies.front().speed);
        return true;
    }
    static bool aim(const World&, double&, double&) { return false; }  // (no game)
    static bool has_instrument(const World&) { return false; }        // (attract mode only flies)

private:
    // The backdrop's rows, kept from frame to frame (render/backdrop.hpp) for a canvas up to 4K's
    // height; a taller one has them computed as drawn.
    static constexpr int kKeptRows = 2160;
    render::BackdropRows rows_;
};
using Space = SpaceOn<double>;

}  // namespace noneuclid::kinds
