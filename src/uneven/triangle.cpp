// The triangle instrument in an uneven world (see triangle.hpp).
#include "uneven/triangle.hpp"

#include <algorithm>
#include <cmath>

namespace noneuclid::uneven {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinAngle = 1e-3;  // radians: three marks closer to a line than this are in one

double wrap(double a) { return std::remainder(a, 2 * kPi); }

// Side i traced from its mark: its points, the heading it arrives with, and the flux of grad psi
// through it, to its right (Simpson's rule on the exact tangent: dx/ds = e^-psi (cos, sin)).
double trace_side(const Metric& m, Vec2 from, double phi, double length, Vec2* out, double& end_phi) {
    constexpr int n = kSidePoints - 1;  // (even: Simpson's rule)
    static_assert(n % 2 == 0);
    Geodesic g{from, phi};
    double flux = 0;
    for (int i = 0; i <= n; ++i) {
        if (i > 0) g = step(m, g, 1.0, length / n);
        out[i] = g.x;
        const MetricAt at = m.at(g.x);
        const double f = std::exp(-at.psi) * (at.grad.x * std::sin(g.phi) - at.grad.y * std::cos(g.phi));
        flux += f * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
    }
    end_phi = g.phi;
    return flux * length / n / 3;
}

// Whether chart point p lies inside the closed polygon of the three sides (every 4th point).
bool inside(const Triangle& t, Vec2 p) {
    bool in = false;
    Vec2 a = t.path[2][kSidePoints - 1];
    for (int s = 0; s < 3; ++s)
        for (int i = 0; i < kSidePoints; i += 4) {
            const Vec2 b = t.path[s][i];
            if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
            a = b;
        }
    return in;
}

}  // namespace

bool shoot(const Metric& m, Vec2 from, Vec2 to, double& phi, double& length) {
    const Vec2 d = to - from;
    phi = std::atan2(d.y, d.x);
    length = std::exp(m.at(0.5 * (from + to)).psi) * std::hypot(d.x, d.y);
    for (int it = 0; it < 30; ++it) {
        const Vec2 e = exp_map(m, from, phi, length).x - to;
        if (std::hypot(e.x, e.y) < 1e-12) return true;
        const double h = 1e-7;
        const Vec2 a = (1 / h) * (exp_map(m, from, phi + h, length).x - to - e);
        const Vec2 b = (1 / h) * (exp_map(m, from, phi, length + h).x - to - e);
        const double det = cross(a, b);  // [a b] (dphi, dlength) = -e
        if (!(std::fabs(det) > 0)) return false;
        // Damped: at most 0.2 rad and a fifth of the length a step, the length kept positive.
        const double dphi = -cross(e, b) / det, dlength = -cross(a, e) / det;
        const double k = std::min({1.0, 0.2 / std::fabs(dphi), 0.2 * length / std::fabs(dlength)});
        phi += k * dphi;
        length += k * dlength;
    }
    return false;
}

void measure(const Metric& m, Triangle& t) {
    t.valid = false;
    double phi[3], end[3], flux = 0;
    for (int i = 0; i < 3; ++i) {
        const Vec2 from = t.mark[i], to = t.mark[(i + 1) % 3];
        if (!(std::hypot(to.x - from.x, to.y - from.y) > 1e-6)) return;  // (coincident marks)
        double length;
        if (!shoot(m, from, to, phi[i], length)) return;
        t.side[(i + 2) % 3] = length;
        flux += trace_side(m, from, phi[i], length, t.path[i], end[i]);
    }
    double sum = 0;
    for (int i = 0; i < 3; ++i) {  // at mark i: side i leaves, side i - 1 arrives
        t.angle[i] = std::fabs(wrap(phi[i] - (end[(i + 2) % 3] + kPi)));
        if (t.angle[i] < kMinAngle || t.angle[i] > kPi - kMinAngle) return;
        sum += t.angle[i];
    }
    t.excess = sum - kPi;
    // The flux was taken to the right of each side: outward when the sides go round
    // counter-clockwise (the traced polygon's signed area: its marks alone can say otherwise
    // where the sides bow).
    double turn = 0;
    Vec2 a = t.path[2][kSidePoints - 1];
    for (const auto& side : t.path)
        for (const Vec2& b : side) turn += cross(a, b), a = b;
    t.curvature = turn > 0 ? -flux : flux;
    // The area: e^{2 psi} at the midpoints of a grid over the chart triangle's bounding box.
    Vec2 lo = t.path[0][0], hi = lo;
    for (const auto& side : t.path)
        for (const Vec2& p : side) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    const double dx = (hi.x - lo.x) / kAreaGrid, dy = (hi.y - lo.y) / kAreaGrid;
    double area = 0;
    for (int j = 0; j < kAreaGrid; ++j)
        for (int i = 0; i < kAreaGrid; ++i) {
            const Vec2 p{lo.x + (i + 0.5) * dx, lo.y + (j + 0.5) * dy};
            if (inside(t, p)) area += std::exp(2 * m.at(p).psi);
        }
    t.area = area * dx * dy;
    t.valid = true;
}

}  // namespace noneuclid::uneven
