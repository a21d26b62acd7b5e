#include "world/budget.hpp"

#include <algorithm>
#include <vector>

namespace noneuclid::world {

namespace {
struct Totals {
    long bodies = 0, vertices = 0, points = 0;
};
Totals totals(const Scene& scene) {
    Totals t;
    for (const SceneBody& b : scene.bodies) {
        ++t.bodies;
        t.vertices += static_cast<long>(b.vertices.size());
        t.points += drawn_points(static_cast<long>(b.vertices.size()), b.tessellation);
    }
    return t;
}
// "1,048,576"
std::string grouped(long v) {
    // Built forwards rather than with insert(): g++ 12 -O2 warns falsely (-Wrestrict) on insert here.
    const std::string digits = std::to_string(v);
    std::string s;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && digits[i - 1] != '-' && (digits.size() - i) % 3 == 0) s += ',';
        s += digits[i];
    }
    return s;
}
bool over(const char* what, long want, long limit, const char* fix, std::string& why) {
    if (want <= limit) return false;
    why = std::string("it would have ") + grouped(want) + " " + what + ", over the " + grouped(limit) +
          " a world may have: " + fix;
    return true;
}
// "64 MiB", or the bytes grouped below a MiB.
std::string grouped_bytes(long long v) {
    return v >= (1LL << 20) && v % (1LL << 20) == 0 ? grouped(static_cast<long>(v >> 20)) + " MiB"
                                                   : grouped(static_cast<long>(v)) + " bytes";
}
// The bytes of the scene's images, each counted once however many bodies share it.
long long scene_image_bytes(const Scene& scene) {
    std::vector<const Image*> seen;
    long long bytes = 0;
    auto count = [&](const std::shared_ptr<const Image>& im) {
        if (!im || std::find(seen.begin(), seen.end(), im.get()) != seen.end()) return;
        seen.push_back(im.get());
        bytes += image_bytes(*im);
    };
    for (const SceneBody& b : scene.bodies) count(b.texture);
    count(scene.game.asteroid_texture);
    return bytes;
}
}  // namespace

long long image_bytes(const Image& image) {
    return static_cast<long long>(image.texels.size()) * static_cast<long long>(sizeof(uint32_t));
}

bool images_allow(long long held, long long more, std::string& why) {
    if (held + more <= Budget::kImageBytes) return true;
    why = "the scene's texture images would take " + grouped_bytes(held + more) + " decoded, over the " +
          grouped_bytes(Budget::kImageBytes) + " a world may have: use fewer or smaller images";
    return false;
}

long drawn_points(long vertices, long tessellation) {
    return vertices * (tessellation > 0 ? tessellation : 1) + 1;
}

bool budget_allows(const Scene& scene, long bodies, long vertices, long tessellation, std::string& why) {
    const Totals t = totals(scene);
    // Each product is checked against its limit before the next one is formed: nothing overflows.
    if (over("vertices in one body", vertices, Budget::kVerticesPerBody, "use fewer vertices", why) ||
        over("bodies", t.bodies + bodies, Budget::kBodies, "use fewer bodies", why))
        return false;
    const long points = drawn_points(vertices, tessellation);
    return !over("vertices", t.vertices + bodies * vertices, Budget::kVertices, "use fewer bodies or vertices", why) &&
           !over("points to draw a frame", t.points + bodies * points, Budget::kPoints,
                 "use fewer bodies or vertices, or a lower tessellation", why);
}

bool within_budget(const Scene& scene, std::string& why) {
    const Totals t = totals(scene);
    long most = 0;
    for (const SceneBody& b : scene.bodies) most = std::max(most, static_cast<long>(b.vertices.size()));
    return !over("vertices in one body", most, Budget::kVerticesPerBody, "use fewer vertices", why) &&
           !over("bodies", t.bodies, Budget::kBodies, "use fewer bodies", why) &&
           !over("vertices", t.vertices, Budget::kVertices, "use fewer bodies or vertices", why) &&
           !over("points to draw a frame", t.points, Budget::kPoints,
                 "use fewer bodies or vertices, or a lower tessellation", why) &&
           images_allow(0, scene_image_bytes(scene), why);
}

}  // namespace noneuclid::world
