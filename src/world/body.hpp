// A body of the world as the engines move and draw it: its pose and motion in the scalar T, its
// local shape, and what the Asteroids game (world/game.hpp) sets on the bodies it uses.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/geometry.hpp"
#include "geometry/coast.hpp"
#include "world/scene.hpp"

namespace noneuclid::world {

template <class T>
struct alignas(geo::kThreadAlign) Body {
    geo::Polar<T> centre;
    T facing{}, speed{}, travel{}, accel{}, accel_dir{}, spin{};
    std::vector<geo::Polar<T>> local;  // (rho, phi from the facing), radians
    geo::Coast<T> coast;               // the straight stretch it is on (geometry/coast.hpp)
    const SceneBody* desc = nullptr;   // name, colour, closed, tessellation, kind
    uint32_t shape = 0;    // counts the changes of `local` (a game's new asteroid): caches follow it
    uint32_t sized = 0;    // counts the changes of local's rho alone (a zoom, Scene::zoom): the same
    // A zoom level's body shown while K = z (World::show_zoom): its picture is a similarity of
    // itself from such frame to frame, its projected radii F(angle) * image_scale, image_scale
    // = 1 / sqrt(z) (render/still_points.hpp scales one frame's into the next). 0: not so.
    float image_scale = 0;
    uint32_t serial = 0;   // a game's asteroid or bullet: its number ("asteroid 12"); 0 otherwise
    bool active = true;    // in the world: moved, drawn, dumped, hit (a game's spare slots are not)
    bool hidden = false;   // in the world but not drawn this frame (the respawned ship blinking)
    bool wrapped = false;  // the last step took it across the limit circle
    int64_t spin_rest = 0; // spin * dt's remainder below the facing's step, carried (geo::turn_by)

    // What the engines (geometry/engine.hpp) read of its description.
    bool closed() const { return desc->closed; }
    int tessellation() const { return desc->tessellation; }
};

}  // namespace noneuclid::world
