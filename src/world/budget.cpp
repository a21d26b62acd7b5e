#include "world/budget.hpp"

#include <algorithm>

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
}  // namespace

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
                 "use fewer bodies or vertices, or a lower tessellation", why);
}

}  // namespace noneuclid::world
