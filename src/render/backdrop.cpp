#include "render/backdrop.hpp"

#include <algorithm>

namespace noneuclid::render {

void draw_backdrop_rows(const Canvas& c, const LimitCircle& circle, const DrawOptions& o, int y0, int y1) {
    const int w = c.width(), bpp = c.format().bytes_per_pixel();
    const detail::SpanPattern bg(c.format().pack(o.background), bpp), out(c.format().pack(o.outside), bpp);
    // The circle in locals: a pixel store may alias anything, and would otherwise make the
    // compiler reload it for every row.
    const double cx = circle.cx, cy = circle.cy, r = circle.r;
    y0 = std::max(y0, 0), y1 = std::min(y1, c.height());
    for (int y = y0; y < y1; ++y) {
        uint8_t* row = c.row(y);
        if (!o.shade_outside) {
            detail::fill_span(row, w, bg);
            continue;
        }
        const ColumnSpan in = columns_inside_circle(cx, cy, r, y, w);
        const int a = std::clamp(in.first, 0, w), b = std::clamp(in.last + 1, 0, w);
        if (a >= b) {
            detail::fill_span(row, w, out);
            continue;
        }
        detail::fill_span(row, a, out);
        detail::fill_span(row + static_cast<std::ptrdiff_t>(a) * bpp, b - a, bg);
        detail::fill_span(row + static_cast<std::ptrdiff_t>(b) * bpp, w - b, out);
    }
}

}  // namespace noneuclid::render
