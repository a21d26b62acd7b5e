// The JSON Lines dump (files/dump.hpp, `noneuclid dump`; docs/file-formats.md): a body's edges
// list their points, ends included, and the screen points mirror them through the projection.
// (The dump as the proof of determinism: tests/world/test_world.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "test_common.hpp"
#include "files/dump.hpp"
#include "world/world.hpp"

using namespace noneuclid::world;
using noneuclid::files::dump_frame;

namespace {

using noneuclid::test::kPi;

TEST(Dump, EdgesListTheirPointsEndsIncludedAndScreenMirrorsThem) {
    // One triangle of vertices 0.1 from its centre at (r 1, theta 0), facing 90 degrees, at
    // K = 0, still.
    Scene s;
    s.curvature = 0;
    s.limit_radius = kPi;
    SceneBody b;
    b.name = "b";
    b.r = 1, b.theta_deg = 0, b.speed = 0, b.direction_deg = 0, b.facing_deg = 90;
    b.vertices = {{0.1, 0}, {0.1, 120}, {0.1, 240}};
    b.tessellation = 4;
    s.bodies.push_back(b);
    World<double> w(s);
    std::string out;
    dump_frame(w, {200, 100, noneuclid::geo::Projection::azimuthal_equidistant}, out);
    // 3 closed edges of 5 points; screen: R = pi fills 50 px (half the smaller side)
    EXPECT_EQ(out.rfind("{\"frame\":0,\"t\":0,\"K\":0,\"bodies\":[{\"name\":\"b\",\"kind\":\"body\",\"center\":[1,0],\"facing\":90,", 0),
              0u)
        << out;
    EXPECT_NE(out.find("\"travel\":[0,0]"), std::string::npos);
    const std::size_t edges = out.find("\"edges\":["), screen = out.find("\"screen\":[");
    ASSERT_NE(edges, std::string::npos);
    ASSERT_NE(screen, std::string::npos);
    const std::string e = out.substr(edges, screen - edges), sc = out.substr(screen);
    EXPECT_EQ(std::count(e.begin(), e.end(), '['), 1 + 3 + 15);   // the list, 3 edges, 15 points
    EXPECT_EQ(std::count(sc.begin(), sc.end(), '['), 1 + 3 + 15);
    // the first vertex: centre (1, 0) plus 0.1 north (facing 90) -> x = 100 + 50/pi * 1, y = 50 - 50/pi * 0.1
    char want[64];
    std::snprintf(want, sizeof want, "\"screen\":[[[%.9g,%.9g]", 100 + 50 / kPi * 1.0, 50 - 50 / kPi * 0.1);
    EXPECT_NE(out.find(want), std::string::npos) << out.substr(screen, 80) << " vs " << want;
    EXPECT_EQ(out.back(), '\n');
}

}  // namespace
