// Lines simplified for the view they are drawn in (docs/earth.md#simplified-to-the-view). A long
// polyline (a coastline) carries a Douglas-Peucker tree of its vertices, made once (DetailTree:
// each node a bracket of the line, the vertex it splits at, how far the bracket's points lie
// from the chord between its ends, and the range of rho they span), and the shape cache
// (geometry/shape_cache.hpp) keeps, each time the view changes, only the vertices the view
// needs: it refines a bracket while its deviation, times the greatest number of pixels a world
// unit covers anywhere in its rho range (DetailScale, from the projection at this K and the
// screen's scale), exceeds kDetailTolerancePx. The walk visits the kept vertices and their
// children alone and allocates nothing (its room is sized with the cache).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/projection.hpp"

namespace noneuclid::geo {

// How far a dropped vertex may lie from the drawn line, in pixels of the view drawn.
inline constexpr double kDetailTolerancePx = 0.6;
// How far past the rim the lines are simplified as at the rim (a zoom's record of a line, drawn
// that much wider than the view: render/still_points.hpp).
inline constexpr double kDetailReach = 1.25;

// A bracket [first, last] of a line's vertices (last == vertex count: a ring's start again)
// split at `split`: `deviation`, the farthest of its inner vertices from the geodesic between
// its ends, and the rho range its vertices span, all in world units as the line was made;
// `left` and `right` the nodes of [first, split] and [split, last] (-1: no inner vertex).
struct DetailNode {
    int32_t split = 0, left = -1, right = -1;
    float deviation = 0, rho_min = 0, rho_max = 0;
};
// A line's tree: its roots (an open line: [0, n - 1]; a ring: [0, far] and [far, n], `far` > 0;
// -1: a root with no inner vertex), and the
// rho of vertex `ref` when the tree was made (the world may scale every rho since, as the earth
// scene's zoom does: deviations and ranges scale with it).
struct DetailTree {
    std::vector<DetailNode> nodes;
    int32_t roots[2] = {-1, -1};
    int32_t root_count = 0;
    int32_t far = 0;
    int32_t ref = 0;
    double ref_rho = 0;
    bool empty() const { return root_count == 0; }
};

// The pixels a world unit covers at distance r from O, at most, in any direction: the view's
// radial and azimuthal scale factors times the screen's scale, sampled at kSamples + 1 rho from
// 0 to the shown disc's rim. Each factor is monotonic in r for every azimuthal view, so the
// greatest over a range is at its ends: `over` takes the samples bracketing the range. Past
// the rim up to kDetailReach times it counts as the rim, farther as nothing (0); the last 1%
// of the rim counts as the rim 1% in (the equidistant
// view's scale grows without bound at the sphere's antipode). `stamp` changes with the view.
struct DetailScale {
    static constexpr int kSamples = 64;
    double px[kSamples + 1] = {};
    double step = 1, per_step = 1;
    uint32_t stamp = 0;
    double K = NAN, scale = NAN, R = NAN;
    Projection projection = Projection::azimuthal_equidistant;

    // For the view of curvature K, limit radius R, projection p, `scale` px per projected unit.
    void update(double k, double r, Projection p, double s) {
        if (k == K && r == R && p == projection && s == scale) return;
        K = k, R = r, projection = p, scale = s;
        ++stamp;
        const double rim = shown_radius(k, r, p), h = rim * 1e-4;
        step = rim / kSamples, per_step = 1 / step;
        for (int i = 0; i <= kSamples; ++i) {
            const double at = std::fmax(std::fmin(i * step, 0.99 * rim), 2 * h);
            const double f = project(k, at, p).rho;
            const double radial = std::fabs(project(k, at + h, p).rho - project(k, at - h, p).rho) / (2 * h);
            const double around = f / S_K(k, at);
            px[i] = s * std::fmax(radial, std::isfinite(around) ? around : 0);
            if (!std::isfinite(px[i])) px[i] = 0;
        }
    }
    // The most pixels a world unit covers over rho in [lo, hi].
    double over(double lo, double hi) const {
        const double a = lo * per_step, b = hi * per_step;
        if (!(a <= kSamples * kDetailReach)) return 0;
        const int i = a >= kSamples ? kSamples : static_cast<int>(a), j = b >= kSamples ? kSamples : static_cast<int>(std::ceil(b));
        return std::fmax(px[i], px[j]);
    }
};

}  // namespace noneuclid::geo
