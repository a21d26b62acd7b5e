// Where the world lands on a canvas: sub-pixel points (SubPoint, 1/256 px, what the rasteriser
// takes), the screen mapping of a canvas for a world at curvature K (ScreenMap), and a curve's
// points on the screen (Spot) with the test that decides whether a chord is close enough to its
// curve (grade). An engine's outline (geometry/engine.hpp) writes Spots into a sink; render's
// ClipSink clips them to the clip circle and hands the polyline to the rasteriser.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "fixed/fixed.hpp"
#include "geometry/projection.hpp"

namespace noneuclid::geo {

struct SubPoint {
    int32_t x = 0, y = 0;  // 1/256 px
};
inline constexpr int kSubBits = 8;
inline constexpr int32_t kSub = 1 << kSubBits;

// From double pixels, saturating at +-2^22 px (far beyond any canvas; clipping keeps the
// direction exact enough there) and mapping NaN to a point far outside.
inline SubPoint to_sub(double x, double y) {
    constexpr double lim = 4194304.0 * kSub;  // 2^22 px
    auto conv = [](double v) {
        if (!(v == v)) return static_cast<int32_t>(lim);  // NaN: far outside
        const double s = v * kSub;
        return static_cast<int32_t>(s > lim ? lim : (s < -lim ? -lim : std::nearbyint(s)));
    };
    return {conv(x), conv(y)};
}
// From Q16.16 pixels (the fixed-point engine's screen points).
constexpr SubPoint to_sub_q16(int32_t x_raw, int32_t y_raw) { return {x_raw >> 8, y_raw >> 8}; }

// A point the projection cannot show: the polyline breaks there. No screen point is ever this
// (to_sub saturates at +-2^30, to_sub_q16 gives at most +-2^23).
inline constexpr SubPoint kBreak{INT32_MIN, INT32_MIN};

// The screen mapping of a canvas for a world at curvature K with limit radius R, seen in
// projection p: the shown disc (geo::shown_radius) fills the smaller side, or is `disc` pixels
// across where the HUD needs room around it (render/layout.hpp), centred, whatever the projection. Centre and pixels per unit of projected radius, the limit circle's radius in px,
// and the clip circle every drawn line keeps within (sub-pixels): the limit circle, or where the
// sphere's antipode lies on it (geo::antipode_circle), kAntipodeMarginPx inside it, since there
// the view turns one point into a whole circle and a point's direction is lost.
inline constexpr double kAntipodeMarginPx = 1.0;
struct DetailScale;  // geometry/detail.hpp

template <class T>
struct ScreenMap {
    T cx{}, cy{}, scale{};
    double rim = 0;        // the limit circle's radius, px
    int64_t clip = 0;      // the clip circle's radius, 1/256 px
    int32_t ox = 0, oy = 0;  // the centre, 1/256 px
    // The view's scale for lines simplified to it (geometry/detail.hpp), set by the frame that
    // draws them; null: such lines are drawn whole.
    const DetailScale* detail = nullptr;
    // Whether the world outside the clip circle is a ball about the antipode smaller than a
    // hemisphere (K > 0 and the shown disc reaches the equator): then an edge whose ends are
    // both outside lies wholly outside (a geodesic between two points of such a ball stays in it).
    bool outside_is_ball = false;

    static ScreenMap of(int width, int height, T K, T R, Projection p, int disc = 0) {
        using std::sqrt;
        const int smaller = width < height ? width : height;
        const int side = disc > 0 && disc < smaller ? disc : smaller;
        ScreenMap m;
        m.cx = T(width) / T(2), m.cy = T(height) / T(2);
        const T rho = rim_rho(K, R, p);
        m.scale = T(side) / T(2) / rho;
        m.rim = side / 2.0;
        double clip = m.rim;
        T a{};
        if (antipode_circle(K, p, a)) clip = std::fmin(clip, static_cast<double>(a * m.scale) - kAntipodeMarginPx);
        m.clip = static_cast<int64_t>(std::fmax(clip, 0.0) * kSub);
        m.ox = static_cast<int32_t>(width) * (kSub / 2), m.oy = static_cast<int32_t>(height) * (kSub / 2);
        const double k = static_cast<double>(K), r = static_cast<double>(shown_radius(K, R, p));
        m.outside_is_ball = k > 0 && k * r * r >= 0.999 * 2.4674011002723395;  // r >= pi / 2 sqrt K
        return m;
    }
    // The same for a canvas (anything with width() and height()).
    template <class Canvas>
    static ScreenMap of(const Canvas& c, T K, T R, Projection p, int disc = 0) requires requires { c.width() + c.height(); }
    {
        return of(c.width(), c.height(), K, R, p, disc);
    }
    // Whether a screen point lies within the clip circle.
    bool inside(SubPoint s) const {
        const int64_t dx = int64_t{s.x} - ox, dy = int64_t{s.y} - oy;
        return dx * dx + dy * dy <= clip * clip;
    }
};

// A screen point in px as a sub-pixel point: straight from Q16.16 in fixed point, no floating
// point between the world and the pixels.
template <class T>
SubPoint to_pixels(const ScreenPoint<T>& p) {
    if constexpr (std::is_same_v<T, fx::fixed>)
        return to_sub_q16(p.x.raw(), p.y.raw());
    else
        return to_sub(static_cast<double>(p.x), static_cast<double>(p.y));
}

// The largest distance, in sub-pixels, a drawn chord may keep from its curve: 0.35 px.
inline constexpr int64_t kChordTolerance = 90;

// A point of a curve on the screen. `in`: shown and within the clip circle.
struct Spot {
    SubPoint at{};
    bool shown = false;
    bool in = false;
};
template <class T>
Spot spot_at(const ScreenMap<T>& m, SubPoint at) {
    return {at, true, m.inside(at)};
}
// Where projection p shows the point of polar coordinates q, as a Spot (not shown where p
// cannot show it).
template <class T>
Spot polar_spot(const ScreenMap<T>& m, T K, Polar<T> q, Projection p) {
    const ProjectedPoint<T> pp = project_polar(K, q, p);
    if (!pp.visible) return Spot{};
    return spot_at(m, to_pixels(ScreenPoint<T>{m.cx + m.scale * pp.X, m.cy - m.scale * pp.Y}));
}

// How far the curve through a, m and b (m the curve's point halfway along it) departs from
// the chord a -> b, in grades: kFlat, within kChordTolerance (the chord may be drawn); kOneCut,
// within 3 times it (each half of the curve is then within 3/4 of it: a smooth curve's
// departure shrinks fourfold when it is halved); kBent, more, or m not between a and b. The
// distance of m from the chord's line is measured against the chord's length approximated as
// max(|dx|, |dy|) + min(|dx|, |dy|) / 4, within 3% above it and less than 15% below, with the
// tolerance 3% less: the test never passes a point farther than the tolerance. In 64-bit
// integers, the same on every machine; coordinates 2^30 sub-pixels apart are kBent.
enum Grade { kFlat, kOneCut, kBent };
[[gnu::always_inline]] inline Grade grade(SubPoint a, SubPoint m, SubPoint b) {
    const int64_t dx = int64_t{b.x} - a.x, dy = int64_t{b.y} - a.y;
    const int64_t ex = int64_t{m.x} - a.x, ey = int64_t{m.y} - a.y;
    constexpr uint64_t kFar = uint64_t{1} << 30;
    if ((static_cast<uint64_t>(dx + kFar) | static_cast<uint64_t>(dy + kFar) | static_cast<uint64_t>(ex + kFar) |
         static_cast<uint64_t>(ey + kFar)) >= 2 * kFar)
        return kBent;
    const int64_t adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    const int64_t length = adx > ady ? adx + ady / 4 : ady + adx / 4;
    const int64_t cross = dx * ey - dy * ex, off = cross < 0 ? -cross : cross;
    const int64_t slack = (kChordTolerance * 32 / 33) * length;  // (3% less)
    const int64_t along = dx * ex + dy * ey;
    if (along < -slack || along > dx * dx + dy * dy + slack) return kBent;
    if (length == 0) return (ex < 0 ? -ex : ex) + (ey < 0 ? -ey : ey) <= kChordTolerance ? kFlat : kBent;
    return off <= slack ? kFlat : off <= 3 * slack ? kOneCut : kBent;
}

}  // namespace noneuclid::geo
