// Screen points: where the world's points land on a canvas, as the rasteriser's sub-pixel
// points (SubPoint), and the list a body's points are written to: one polyline, with kBreak
// where the projection cannot show a point.
#pragma once

#include <cstddef>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "fixed/fixed.hpp"
#include "geometry/geometry.hpp"
#include "render/canvas.hpp"
#include "render/raster.hpp"

namespace noneuclid::render {

// A point the projection cannot show: the polyline breaks there. No screen point is ever this
// (to_sub saturates at +-2^30, to_sub_q16 gives at most +-2^23).
inline constexpr SubPoint kBreak{INT32_MIN, INT32_MIN};

// The screen mapping of a canvas for a world at curvature K with limit radius R, seen in
// projection p: the shown disc (geo::shown_radius) fills the smaller side, centred, whatever the
// projection. Centre and pixels per unit of projected radius, the limit circle's radius in px,
// and the clip circle every drawn line keeps within (sub-pixels): the limit circle, or where the
// sphere's antipode lies on it (geo::antipode_circle), kAntipodeMarginPx inside it, since there
// the view turns one point into a whole circle and a point's direction is lost.
inline constexpr double kAntipodeMarginPx = 1.0;
template <class T>
struct ScreenMap {
    T cx{}, cy{}, scale{};
    double rim = 0;        // the limit circle's radius, px
    int64_t clip = 0;      // the clip circle's radius, 1/256 px
    int32_t ox = 0, oy = 0;  // the centre, 1/256 px
    // Whether the world outside the clip circle is a ball about the antipode smaller than a
    // hemisphere (K > 0 and the shown disc reaches the equator): then an edge whose ends are
    // both outside lies wholly outside (a geodesic between two points of such a ball stays in it).
    bool outside_is_ball = false;

    static ScreenMap of(int width, int height, T K, T R, geo::Projection p) {
        using std::sqrt;
        const int side = width < height ? width : height;
        ScreenMap m;
        m.cx = T(width) / T(2), m.cy = T(height) / T(2);
        const T rho = geo::rim_rho(K, R, p);
        m.scale = T(side) / T(2) / rho;
        m.rim = side / 2.0;
        double clip = m.rim;
        T a{};
        if (geo::antipode_circle(K, p, a)) clip = std::fmin(clip, static_cast<double>(a * m.scale) - kAntipodeMarginPx);
        m.clip = static_cast<int64_t>(std::fmax(clip, 0.0) * kSub);
        m.ox = static_cast<int32_t>(width) * (kSub / 2), m.oy = static_cast<int32_t>(height) * (kSub / 2);
        const double k = static_cast<double>(K), r = static_cast<double>(geo::shown_radius(K, R, p));
        m.outside_is_ball = k > 0 && k * r * r >= 0.999 * 2.4674011002723395;  // r >= pi / 2 sqrt K
        return m;
    }
    static ScreenMap of(const Canvas& c, T K, T R, geo::Projection p) { return of(c.width(), c.height(), K, R, p); }
    // Whether a screen point lies within the clip circle.
    bool inside(SubPoint s) const {
        const int64_t dx = int64_t{s.x} - ox, dy = int64_t{s.y} - oy;
        return dx * dx + dy * dy <= clip * clip;
    }
};

// A screen point in px as a sub-pixel point: straight from Q16.16 in fixed point, no floating
// point between the world and the pixels.
template <class T>
SubPoint to_pixels(const geo::ScreenPoint<T>& p) {
    if constexpr (std::is_same_v<T, fx::fixed>)
        return to_sub_q16(p.x.raw(), p.y.raw());
    else
        return to_sub(static_cast<double>(p.x), static_cast<double>(p.y));
}


}  // namespace noneuclid::render
