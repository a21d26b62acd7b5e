// What one world may hold, so that no scene (a file, a grid, the stress scene's parameters) can
// ask for more memory or time than a frame can have: every value of a scene file may be in its
// range and their product still too much (an axis grid with spacing 0.01, step 0.001 and length
// 10000 asks for 4e13 vertices). Checked while a scene is built, before the bodies are made,
// and for the scene as a whole; what is over gets one sentence that says what to lower.
#pragma once

#include <string>

#include "world/image.hpp"
#include "world/scene.hpp"

namespace noneuclid::world {

struct Budget {
    static constexpr long kBodies = 20000;            // bodies in a world, grid lines included
    static constexpr long kVerticesPerBody = 10000;   // vertices of one body
    static constexpr long kVertices = 1L << 19;       // vertices of all bodies: 524,288
    static constexpr long kPoints = 1L << 20;         // points drawn a frame: 1,048,576
    // Decoded texture images, counted once per image however many bodies share it: sixteen
    // images of the largest size (world/image.hpp), 64 MiB.
    static constexpr long long kImageBytes = 64LL << 20;
};

// The bytes `image` takes decoded (its texels).
long long image_bytes(const Image& image);

// Whether images already taking `held` bytes can take one more of `more` bytes; false with a
// sentence in `why` (without a full stop), whose end says what to lower.
bool images_allow(long long held, long long more, std::string& why);

// The points a body of `vertices` vertices puts on screen a frame, its edges tessellated at
// `tessellation` (an upper bound: a closed body's edges).
long drawn_points(long vertices, long tessellation);

// Whether `scene` can take `bodies` more bodies of `vertices` vertices each at `tessellation`;
// false with a sentence in `why` (without a full stop), whose end says what to lower.
bool budget_allows(const Scene& scene, long bodies, long vertices, long tessellation, std::string& why);

// Whether the scene as built is within the budget (its distinct images included); false with a
// sentence in `why`.
bool within_budget(const Scene& scene, std::string& why);

}  // namespace noneuclid::world
