// Screen points: where the world's points land on a canvas, as the rasteriser's sub-pixel
// points (SubPoint), and the list a body's points are written to: one polyline, with kBreak
// where the projection cannot show a point.
#pragma once

#include <cstddef>
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

// The screen mapping of the canvas: the limit circle R fills the smaller side, centred. Centre
// and pixels per unit of projected radius.
template <class T>
struct ScreenMap {
    T cx, cy, scale;
    static ScreenMap of(int width, int height, T R) {
        const int side = width < height ? width : height;
        return {T(width) / T(2), T(height) / T(2), T(side) / T(2) / R};
    }
    static ScreenMap of(const Canvas& c, T R) { return of(c.width(), c.height(), R); }
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

namespace detail {
// Where a body's screen points stand: entries written, and whether a run of visible points is
// under way (a hidden point then writes kBreak).
struct Cursor {
    std::size_t count = 0;
    bool open = false;
};
// One projected point (X, Y) mapped to the screen, or a break where it is hidden.
template <class T>
void put_point(SubPoint* out, Cursor& c, const ScreenMap<T>& m, bool visible, T X, T Y) {
    if (!visible) {
        if (c.open) out[c.count++] = kBreak, c.open = false;
        return;
    }
    out[c.count++] = to_pixels(geo::ScreenPoint<T>{m.cx + m.scale * X, m.cy - m.scale * Y});
    c.open = true;
}
}  // namespace detail

}  // namespace noneuclid::render
