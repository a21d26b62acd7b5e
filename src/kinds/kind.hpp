// The contract of a kind of world: what a world must give the session (app/session.cpp), the C
// interface, the firmware, dump and render, so that each drives every kind alike. A kind is a
// type K with a public `world` (its state, a World below) and its own drawing; the kinds' table
// (kinds/kinds.hpp) names each kind, says which scenes it takes and on which engines it runs.
//
// What a world gives (the concept World):
//  - its clock and state: time (world seconds, the steps' dt summed), frame (steps taken), K and
//    R (the curvature and the limit radius, as its scalar), bodies (each with desc, active,
//    speed), scene();
//  - step(dt), and the actions (world/action.hpp): press, release, held;
//  - its instruments: gauges() (each with on() and reading(), world::GaugeReading), measuring(),
//    place_mark(at) (a tap on the live instrument);
//  - its game: game(), a world::Game (one that is off when the scene has none);
//  - zoom(): its zoom's reading (on false where it has none).
// What the kind adds (the concept WorldKind):
//  - prepare(pool): its drawing's buffers, sized once for the world and a pool of threads;
//  - draw(canvas, options, backdrop, pool): the world in a view (no HUD), allocating nothing;
//  - next_view(p), view_words(p, language), marks_in(p): the views it has, in the order the
//    projection control cycles them, the HUD's name of each, and whether a tap in view p is a
//    point of the world (mark_at);
//  - note(out, size, language): the HUD's extra line (the zoom's reach, the bumps' gain), false
//    for none;
//  - legend(keys, scene): the HUD's controls line for a keyboard (keys) or the kiosk's buttons;
//  - dump(options, line): one JSON Lines frame of `noneuclid dump` (docs/file-formats.md);
//  - ship_speed(world, speed): whether a ship flies (the autopilot's and the engine hum's), and its
//    speed; aim(world, turn, distance): the game's target from the ship's nose, false for none;
//    has_instrument(world): whether the live instrument is there to turn on (attract mode
//    measures with it while K sweeps).
// Recording needs nothing of a kind: the session records the actions it applies, with the world's
// time, and a replay applies them at the same times, so the same kind replays bit for bit.
#pragma once

#include <concepts>
#include <cstddef>
#include <string>
#include <utility>

#include "files/dump.hpp"
#include "geometry/geometry.hpp"
#include "lang/lang.hpp"
#include "render/canvas.hpp"
#include "render/draw_options.hpp"
#include "render/worker_pool.hpp"
#include "world/action.hpp"
#include "world/instruments.hpp"
#include "world/scene.hpp"

namespace noneuclid::kinds {

template <class W>
concept World = requires(W& w, const W& cw, world::Action a, double dt, geo::Polar<typename W::scalar> at) {
    typename W::scalar;
    requires std::constructible_from<W, const world::Scene&>;
    { cw.time } -> std::convertible_to<double>;
    { cw.frame } -> std::convertible_to<long>;
    { static_cast<double>(cw.K) };
    { static_cast<double>(cw.R) };
    { cw.bodies.size() } -> std::convertible_to<std::size_t>;
    { cw.scene() } -> std::same_as<const world::Scene&>;
    w.step(dt);
    w.press(a);
    w.release(a);
    { cw.held(a) } -> std::same_as<bool>;
    { cw.gauges().size() } -> std::convertible_to<std::size_t>;
    { cw.gauges().back().on() } -> std::same_as<bool>;
    { cw.gauges().back().reading() } -> std::convertible_to<const world::GaugeReading&>;
    { cw.measuring() } -> std::same_as<bool>;
    w.place_mark(at);
    { cw.game().on() } -> std::same_as<bool>;
    { cw.zoom().on } -> std::convertible_to<bool>;
};

template <class K>
concept WorldKind = requires(K& k, const K& ck, const render::Canvas& c, const render::DrawOptions& o, bool backdrop,
                             render::WorkerPool& pool, geo::Projection p, lang::Language l, char* out, std::size_t size,
                             const files::DumpOptions& d, std::string& line, const world::Scene& scene,
                             double& speed) {
    typename K::World;
    requires World<typename K::World>;
    requires std::constructible_from<K, const world::Scene&>;
    { k.world } -> std::convertible_to<typename K::World&>;
    k.prepare(pool);
    k.draw(c, o, backdrop, pool);
    { K::next_view(p) } -> std::same_as<geo::Projection>;
    { K::view_words(p, l) } -> std::same_as<const char*>;
    { K::marks_in(p) } -> std::same_as<bool>;
    { ck.note(out, size, l) } -> std::same_as<bool>;
    { K::legend(backdrop, scene) } -> std::same_as<lang::Text>;
    ck.dump(d, line);
    { K::ship_speed(std::as_const(k.world), speed) } -> std::same_as<bool>;
    { K::aim(std::as_const(k.world), speed, speed) } -> std::same_as<bool>;
    { K::has_instrument(std::as_const(k.world)) } -> std::same_as<bool>;
};

// ship_speed and aim for a world of the plane's bodies and game (the worlds of constant and of
// uneven curvature): its controlled body that is active, and world::Game::aim.
template <class W>
bool plane_ship_speed(const W& w, double& speed) {
    for (const auto& b : w.bodies)
        if (b.desc->controlled && b.active) {
            speed = static_cast<double>(b.speed);
            return true;
        }
    return false;
}
template <class W>
bool plane_aim(const W& w, double& turn, double& distance) {
    return w.game().on() && w.game().aim(w, turn, distance);
}

}  // namespace noneuclid::kinds
