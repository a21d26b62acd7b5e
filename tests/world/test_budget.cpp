// The world's budget (world/budget.hpp): what a world may hold, refused with a sentence before
// anything is built, whatever the product of values each within its range. (A scene file over
// it, named with its place: tests/files/test_scene_file.cpp.)
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "test_common.hpp"
#include "world/budget.hpp"
#include "world/scene.hpp"

using namespace noneuclid::world;

namespace {

using noneuclid::test::kPi;

// Values each within their range can multiply past what a world may hold: refused with a
// sentence, before anything is allocated, whatever the product (here up to 4e13 vertices).
TEST(Budget, GridsAndTheStressSceneOverItAreRefusedBeforeAnythingIsBuilt) {
    Scene s;
    s.limit_radius = 1e4;
    std::string why;
    EXPECT_FALSE(add_axis_grid(s, 0.01, 1e4, 0.001, {1, 2, 3}, why));
    EXPECT_TRUE(s.bodies.empty());
    EXPECT_EQ(why, "it would have 20,000,001 vertices in one body, over the 10,000 a world may have: use fewer vertices "
                   "(a larger spacing or step, a shorter length, fewer lines)");
    s.limit_radius = kPi;
    EXPECT_FALSE(add_radial_grid(s, 360, 10, 0.002, {1, 2, 3}, why));  // 360 lines of 5,001 vertices
    EXPECT_NE(why.find("1,800,360 vertices, over the 524,288"), std::string::npos) << why;
    EXPECT_TRUE(s.bodies.empty());
    // Many lines, each small: the count of bodies.
    s.limit_radius = 1e4;
    EXPECT_FALSE(add_axis_grid(s, 0.01, 0.1, 0.05, {1, 2, 3}, why));
    EXPECT_NE(why.find("4,000,002 bodies, over the 20,000"), std::string::npos) << why;
    // The stress scene's parameters, each at its documented maximum.
    Scene stress;
    EXPECT_FALSE(builtin_scene("stress", {100000, 10000, 256}, stress, &why));
    EXPECT_EQ(why.rfind("the stress scene: it would have ", 0), 0u) << why;
    EXPECT_TRUE(stress.bodies.empty());
    EXPECT_FALSE(builtin_scene("stress", {4000, 200, 8}, stress, &why));  // 800,000 vertices
    EXPECT_NE(why.find("800,000 vertices"), std::string::npos) << why;
    // Just within: built, and within_budget agrees.
    ASSERT_TRUE(builtin_scene("stress", {2000, 64, 8}, stress, &why)) << why;
    EXPECT_TRUE(within_budget(stress, why)) << why;
    // Every built-in scene is well within.
    for (const std::string& name : builtin_scene_names()) {
        Scene b;
        ASSERT_TRUE(builtin_scene(name, {}, b, &why)) << name;
        EXPECT_TRUE(within_budget(b, why)) << name << ": " << why;
    }
}

}  // namespace

// Decoded images count against the budget once each, however many bodies share one (issue 33):
// the bytes are the texels' (4 a texel), added up independently here.
TEST(Budget, ImagesCountOnceEachAgainstTheBudget) {
    auto image = [](int side) {
        auto im = std::make_shared<Image>();
        im->width = im->height = side;
        im->texels.assign(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0);
        return im;
    };
    EXPECT_EQ(image_bytes(*image(1024)), 4LL << 20);
    Scene s;
    std::string why;
    SceneBody b;
    b.vertices = {{0.1, 0}, {0.1, 120}, {0.1, 240}};
    // 2,048 bodies sharing one 1024 x 1024 image: 4 MiB, not 8 GiB.
    b.texture = image(1024);
    s.bodies.assign(2048, b);
    EXPECT_TRUE(within_budget(s, why)) << why;
    // Sixteen distinct images of the largest size are the budget; a seventeenth is over it.
    s.bodies.clear();
    for (int i = 0; i < 16; ++i) {
        b.texture = image(1024);
        s.bodies.push_back(b);
    }
    EXPECT_TRUE(within_budget(s, why)) << why;
    s.game.asteroid_texture = image(64);  // the game's asteroid image counts too
    EXPECT_FALSE(within_budget(s, why));
    EXPECT_EQ(why, "the scene's texture images would take 67,125,248 bytes decoded, over the 64 MiB a world may have: use "
                   "fewer or smaller images");
    EXPECT_EQ(67125248LL, 16 * 1024 * 1024 * 4LL + 64 * 64 * 4LL);
    // As a scene is read: the images held and the next one.
    EXPECT_TRUE(images_allow(60LL << 20, 4LL << 20, why)) << why;
    EXPECT_FALSE(images_allow(60LL << 20, (4LL << 20) + 4, why));
    EXPECT_NE(why.find("over the 64 MiB"), std::string::npos) << why;
}
