#include "render/backdrop.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace noneuclid::render {

namespace {
// Blends the anti-aliased circle into row y over the columns [x0, x1]: coverage 1 at distance
// w/2 from it, falling to 0 at w/2 + 1/2 (coverage by the pixel centre's distance).
void blend_circle_row(const Canvas& c, const LimitCircle& circle, double half, Rgb color, int y, int x0, int x1) {
    const double dy = y + 0.5 - circle.cy;
    for (int x = std::max(x0, 0); x <= x1 && x < c.width(); ++x) {
        const double dx = x + 0.5 - circle.cx;
        const double off = std::fabs(std::sqrt(dx * dx + dy * dy) - circle.r);
        const double cover = std::fmin(1.0, half + 0.5 - off);
        if (cover > 0) c.blend(x, y, color, static_cast<int>(cover * 255 + 0.5));
    }
}
}  // namespace

void draw_backdrop_rows(const Canvas& c, const LimitCircle& circle, const DrawOptions& o, int y0, int y1) {
    const int w = c.width(), bpp = c.format().bytes_per_pixel();
    const detail::SpanPattern bg(c.format().pack(o.background), bpp), out(c.format().pack(o.outside), bpp);
    uint8_t rim[4];  // one pixel of the circle's colour
    {
        const uint32_t word = c.format().pack(o.rim);
        std::memcpy(rim, &word, 4);
    }
    // The circle in locals: a pixel store may alias anything, and would otherwise make the
    // compiler reload it for every row.
    const double cx = circle.cx, cy = circle.cy, r = circle.r;
    const double half = o.line_width / (2.0 * kSub);  // the circle line's half width, px
    y0 = std::max(y0, 0), y1 = std::min(y1, c.height());
    for (int y = y0; y < y1; ++y) {
        uint8_t* row = c.row(y);
        if (o.shade_outside) {
            const ColumnSpan in = columns_inside_circle(cx, cy, r, y, w);
            const int a = std::clamp(in.first, 0, w), b = std::clamp(in.last + 1, 0, w);
            if (a >= b) {
                detail::fill_span(row, w, out);
            } else {
                detail::fill_span(row, a, out);
                detail::fill_span(row + static_cast<std::ptrdiff_t>(a) * bpp, b - a, bg);
                detail::fill_span(row + static_cast<std::ptrdiff_t>(b) * bpp, w - b, out);
            }
        } else {
            detail::fill_span(row, w, bg);
        }
        if (!o.rim_line || std::fabs(y + 0.5 - cy) >= r + half + 0.5) continue;
        if (o.antialias) {  // the pixels within half + 1/2 of the circle, blended
            const ColumnSpan a = columns_inside_circle(cx, cy, r + half + 0.5, y, w);
            const ColumnSpan b = columns_inside_circle(cx, cy, r - half - 0.5, y, w);
            if (b.first > b.last) {
                blend_circle_row(c, circle, half, o.rim, y, a.first, a.last);
            } else {
                blend_circle_row(c, circle, half, o.rim, y, a.first, b.first - 1);
                blend_circle_row(c, circle, half, o.rim, y, b.last + 1, a.last);
            }
            continue;
        }
        // The pixels whose centres lie within half the line's width of the circle: inside the
        // circle of radius r + half and not inside the one of radius r - half.
        const ColumnSpan outer = columns_inside_circle(cx, cy, r + half, y, w);
        const ColumnSpan inner = columns_inside_circle(cx, cy, r - half, y, w);
        auto line = [&](int x0, int x1) {  // columns [x0, x1]: short runs, written pixel by pixel
            x0 = std::max(x0, 0), x1 = std::min(x1, w - 1);
            uint8_t* p = row + static_cast<std::ptrdiff_t>(x0) * bpp;
            for (int x = x0; x <= x1; ++x, p += bpp) {
                if (bpp == 2) std::memcpy(p, rim, 2);
                else if (bpp == 4) std::memcpy(p, rim, 4);
                else std::memcpy(p, rim, 3);
            }
        };
        if (inner.first > inner.last) {
            line(outer.first, outer.last);
        } else {
            line(outer.first, inner.first - 1);
            line(inner.last + 1, outer.last);
        }
    }
}

}  // namespace noneuclid::render
