// Screen points for the double engine as GLM vectors (the fixed engine uses
// geo::ScreenPoint<fixed>, geometry.hpp): x = cx + scale rho cos theta, y = cy - scale rho sin
// theta (screen y grows downward; theta is counter-clockwise as seen).
#pragma once

#include <cmath>
#include <glm/vec2.hpp>

namespace noneuclid::geo {

inline glm::dvec2 screen_point(double rho, double theta, glm::dvec2 centre, double scale) {
    return centre + scale * rho * glm::dvec2(std::cos(theta), -std::sin(theta));
}

}  // namespace noneuclid::geo
