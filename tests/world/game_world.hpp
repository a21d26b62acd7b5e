// The game tests' world: the built-in asteroids scene at a given K (its levels kept at that K),
// and how many bodies of a kind are active.
#pragma once

#include <gtest/gtest.h>

#include "world/world.hpp"

namespace noneuclid::test {

inline world::Scene game_scene(double K = 0) {
    world::Scene s;
    if (!world::builtin_scene("asteroids", {}, s)) ADD_FAILURE() << "no asteroids scene";
    s.curvature = K;
    s.game.levels = {K};
    return s;
}

template <class W>
int count(const W& w, world::BodyKind k) {
    int n = 0;
    for (const auto& b : w.bodies) n += b.active && b.desc->kind() == k;
    return n;
}

}  // namespace noneuclid::test
