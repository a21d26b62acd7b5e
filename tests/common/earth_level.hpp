// The built-in earth scene cut to what one of its zoom levels draws (world::Scene::zoom): the
// level of the scene's start, bent (halved for every K: what K = -1, 0 or a preset shows) or
// plain (for K equal to the zoom alone), and the ship. Tests of the lines take one level at a
// time, as the world shows them.
#pragma once

#include <gtest/gtest.h>

#include "world/scene.hpp"

namespace noneuclid::test {

inline world::Scene earth_level(const world::SceneParams& p, bool bent = true) {
    world::Scene s;
    EXPECT_TRUE(world::builtin_scene("earth", p, s));
    const world::ZoomLevel* level = nullptr;
    for (const world::ZoomLevel& l : s.zoom.levels)
        if (l.bent == bent && l.curvature >= s.zoom.start && (!level || l.curvature < level->curvature)) level = &l;
    EXPECT_NE(level, nullptr);
    world::Scene out = s;
    out.bodies.clear();
    out.zoom = {};
    for (int i = 0; i < static_cast<int>(s.bodies.size()); ++i)
        if (s.bodies[i].controlled || (level && i >= level->first && i < level->first + level->count))
            out.bodies.push_back(s.bodies[i]);
    return out;
}

}  // namespace noneuclid::test
