// The raster of a filled body, row by row (render/fill.hpp plans it, fill_pixels.hpp has the
// engines' pixels). A FillJob is one body's fill for one frame: the projected outline as a
// polyline that follows the projected geodesic edges within `zone` (1/256 px), the rows it
// reaches, and the engine's two pixel functions. On each row:
//  - the polyline's crossings of the row's pixel centres, and its zones: the pixels whose centre
//    lies within `zone` of a segment;
//  - between two zones the outline is not crossed, so every pixel there is inside or every one
//    outside: inside when an odd number of crossings lie to its left (the even-odd rule). Those
//    runs are painted whole (`span`, or one colour);
//  - in a zone each pixel is tested exactly (`test`: the pixel taken back to the body's frame and
//    the 3-vector inside test, geo::point_in_polygon's), and under anti-aliasing painted with a
//    coverage from its distance to the polyline.
// So a pixel is lit exactly when its centre is inside the projected geodesic polygon, wherever
// the polyline is within `zone` of the true edges. A body holding the sphere's antipode (K > 0)
// has the antipode's circle as a second boundary (`rim`); a body the polyline cannot follow
// (a point the projection cannot show) is tested pixel by pixel over its rows (`brute`). Every
// row is cut to the shown disc (`clip_*`), the limit circle or the antipode's margin.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/canvas.hpp"
#include "render/raster.hpp"

namespace noneuclid::render {

// What a row's anti-aliased pixels need: the segments near the row, and the rim.
struct FillSegment {
    SubPoint a, b;
    int64_t length = 0;  // |b - a|, 1/256 px (at least 1)
};
struct RowCover {
    const FillSegment* segments = nullptr;
    std::size_t count = 0;
    bool rim = false;
    int64_t rim_cx = 0, rim_cy = 0, rim_r = 0;  // 1/256 px
    int y = 0;
};
// The coverage (0..255) of pixel (x, cover.y) whose centre is inside or not: 1/2 plus or minus
// its distance to the nearest segment (or the rim), clamped to [0, 1].
int fill_coverage(const RowCover& cover, int x, bool inside);

struct FillJob {
    bool on = false;     // something to draw this frame
    bool brute = false;  // every pixel of [left, right) x [top, bottom) tested
    bool aa = false;     // anti-aliased edges
    int top = 0, bottom = 0, left = 0, right = 0;  // pixel rows [top, bottom), columns [left, right)
    // The polyline: closed loops (each ends at its first point), kBreak between loops.
    const SubPoint* points = nullptr;
    std::size_t count = 0;
    int32_t zone = 0;  // 1/256 px
    bool rim = false;
    int64_t rim_cx = 0, rim_cy = 0, rim_r = 0;  // the antipode's circle, 1/256 px
    // The shown disc (ScreenMap's clip circle, 1/256 px): only pixels whose centre lies within it
    // are painted, as the outlines are clipped to it (a hard edge; the limit circle is drawn on it).
    int64_t clip_cx = 0, clip_cy = 0, clip_r = int64_t{1} << 40;
    // Runs inside: one colour (`solid`, the packed `word`), or the engine's `span` (a texture).
    bool solid = true;
    uint32_t word = 0;
    const void* body = nullptr;
    void (*span)(const void* body, const Canvas& c, int y, int x0, int x1) = nullptr;
    // Pixels [x0, x1) of row y each tested and painted (with `cover`: anti-aliased).
    void (*test)(const void* body, const Canvas& c, int y, int x0, int x1, const RowCover* cover) = nullptr;
};

// A thread's room for one row of any job it is given: sized by reserve for the longest
// polyline (and the rim); a frame allocates nothing.
struct RowWork {
    std::vector<uint32_t> order, active;  // the polyline's segments by their tops; those near the row
    std::vector<int32_t> crossings;
    struct Zone {
        int64_t from, to;  // 1/256 px
    };
    std::vector<Zone> zones;
    std::vector<FillSegment> near;
    void reserve(std::size_t segments);
};

// Rows [y0, y1) of the job (clamped to its rows and the canvas), painted.
void fill_rows(const Canvas& c, const FillJob& job, int y0, int y1, RowWork& work);

}  // namespace noneuclid::render
