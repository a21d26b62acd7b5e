// The CPU line rasteriser: writes straight into a Canvas (a RAM back buffer or the
// framebuffer itself).
//
// Coordinates are sub-pixel fixed point, 1/256 px (`SubPoint`, int32: +-8 million px).
// Pixel (i, j) covers [i, i+1) x [j, j+1); its centre is (i + 1/2, j + 1/2).
//
// - Clipping: Liang-Barsky against the canvas grown by 2 px, in double, once per line; the
//   per-pixel loop then runs only over the visible part, and every write is also checked, so
//   nothing is ever written outside the canvas (huge or infinite-looking coordinates included).
//   A line whose end points both lie inside is never altered by clipping.
// - Aliased lines (Bresenham with sub-pixel end points): along the major axis, every pixel
//   whose centre coordinate lies in [start, end) (the start included, the end excluded), the
//   pixel containing the exact line's point there. Integer error term, no division per pixel.
// - Anti-aliased lines: the line as a band `width` px wide; in each major-axis column the
//   band covers an interval of the minor axis (width * length / major extent long) and each
//   pixel gets the exact overlap as its coverage (area sampling along the minor axis; Wu's
//   algorithm is the special case of a fixed unit interval). Coverage along a line sums to
//   its length times its width. Blended in 8-bit per channel, in any pixel format.
// - Thick aliased lines: the same band, filling the pixels whose centre it covers.
// - Polylines do not plot a shared end point twice: each segment is half-open. Thin aliased
//   polylines also plot, once each, the pixels of an open polyline's two end points and of
//   each join where the segments do not step along the same axis the same way (a fold back, a
//   turn across a diagonal), where both half-open segments could stop up to a pixel short of
//   it. Every point of a thin polyline is then within 1.12 px (sqrt 1.25) of a plotted
//   pixel's centre.
// - Row bands (RowRange): every function can be told to write only rows [y0, y1). It writes
//   exactly the pixels (and, anti-aliased, the same blends in the same order) that the whole
//   line writes in those rows, and nothing else: clipping still uses the whole canvas, and the
//   loops start at the band's first column by exact integer arithmetic (no walking from the
//   line's start) and stop after its last; only a thin x-major line of at most 64 px is walked
//   whole, each pixel checked against the band. Threads drawing disjoint bands of one canvas
//   (draw_world over a WorkerPool) thus make the same picture as one thread drawing it all.
#pragma once

#include <climits>
#include <cmath>
#include <cstdint>

#include "geometry/screen_map.hpp"
#include "render/canvas.hpp"

namespace noneuclid::render {

using geo::kSub;
using geo::kSubBits;
using geo::SubPoint;
using geo::to_sub;
using geo::to_sub_q16;

using PixelVisitor = void (*)(int x, int y, int alpha, void* context);

struct LineStyle {
    bool antialias = false;
    int32_t width = kSub;  // 1/256 px; 256 = one pixel
};

// Rows [y0, y1) of the canvas (clamped to it): the only rows a call given one writes.
struct RowRange {
    int y0 = 0, y1 = INT_MAX;
};
// The rows a canvas holds (Canvas::band): every row (the faster paths) for a whole canvas.
inline RowRange held_rows(const Canvas& c) { return c.whole() ? RowRange{} : RowRange{c.top(), c.bottom()}; }

// Every pixel a line (or polyline) writes lies in the rows its points span widened by this, in
// 1/256 px: row y is written only if some point's y (1/256 px) is >= y * 256 - row_margin and
// another's is < (y + 1) * 256 + row_margin. Aliased 1 px lines stay within their points' pixel
// rows; bands reach h / 2 <= width / sqrt 2 across (h: the band's extent per column).
constexpr int32_t row_margin(LineStyle style) {
    return (style.antialias || style.width > kSub ? style.width : kSub) + 8;
}

// One segment from a to b. `plot_ends` adds the end points' own pixels, as an open polyline's
// (the half-open rule may leave them out; without it the segment is one piece of a polyline).
void draw_line(const Canvas& c, SubPoint a, SubPoint b, Rgb color, LineStyle style = {}, bool plot_ends = true,
               RowRange rows = {});

// A polyline through n points (closed: back to the first), no pixel of a shared end point
// plotted twice.
void draw_polyline(const Canvas& c, const SubPoint* points, int n, bool closed, Rgb color, LineStyle style = {},
                   RowRange rows = {});

// The same polyline on a width x height grid, each pixel handed to `visit` (x, y, coverage
// 0..255) instead of written: what draw_polyline would write, for tests and tools.
void visit_polyline(int width, int height, const SubPoint* points, int n, bool closed, LineStyle style,
                    PixelVisitor visit, void* context, RowRange rows = {});

// Every pixel whose centre lies outside the circle (cx, cy, r), in px, set to `shade` (the
// shaded area outside the limit circle in the paper's figures). With `blend_alpha` < 255 the
// shade is blended instead.
void shade_outside_circle(const Canvas& c, double cx, double cy, double r, Rgb shade, int blend_alpha = 255);

// The columns [first, last] of row y whose pixel centres lie inside the circle (cx, cy, r), in
// px, on a canvas `width` px wide; last < first when there are none. The columns may reach one
// past the canvas on either side.
struct ColumnSpan {
    int first, last;
};
inline ColumnSpan columns_inside_circle(double cx, double cy, double r, int y, int width) {
    const double dy = y + 0.5 - cy;
    if (!(std::fabs(dy) < r)) return {0, -1};
    const double half = std::sqrt(r * r - dy * dy);
    return {static_cast<int>(std::fmax(-1.0, std::floor(cx - half - 0.5) + 1)),
            static_cast<int>(std::fmin(width, std::ceil(cx + half - 0.5) - 1))};
}

}  // namespace noneuclid::render
