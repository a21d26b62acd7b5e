#include "render/backdrop.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

// A row's columns (BackdropRow's, in full).
struct Row {
    ColumnSpan in, outer, inner;
};
Row row_of(const LimitCircle& circle, const DrawOptions& o, int y, int w) {
    const double cx = circle.cx, cy = circle.cy, r = circle.r;
    const double half = o.line_width / (2.0 * kSub);  // the circle line's half width, px
    const ColumnSpan none{0, -1};
    const bool line = o.rim_line && std::fabs(y + 0.5 - cy) < r + half + 0.5;
    // The line's pixels: within half of the circle, or half + 1/2 (blended) anti-aliased.
    const double outer = o.antialias ? r + half + 0.5 : r + half, inner = o.antialias ? r - half - 0.5 : r - half;
    return {o.shade_outside ? columns_inside_circle(cx, cy, r, y, w) : none,
            line ? columns_inside_circle(cx, cy, outer, y, w) : none, line ? columns_inside_circle(cx, cy, inner, y, w) : none};
}
// A span of columns in 16 bits; false when it does not fit.
bool narrow(ColumnSpan s, BackdropRow::Span& out) {
    if (s.first < INT16_MIN || s.first > INT16_MAX || s.last < INT16_MIN || s.last > INT16_MAX) return false;
    out = {static_cast<int16_t>(s.first), static_cast<int16_t>(s.last)};
    return true;
}
ColumnSpan widen(BackdropRow::Span s) { return {s.first, s.last}; }
}  // namespace

const BackdropRow* BackdropRows::rows(const Canvas& c, const LimitCircle& circle, const DrawOptions& o) {
    const std::size_t h = static_cast<std::size_t>(std::max(c.height(), 0));
    if (h == 0 || rows_.capacity() < h) return nullptr;
    const bool same = rows_.size() == h && width_ == c.width() && circle_.cx == circle.cx && circle_.cy == circle.cy &&
                      circle_.r == circle.r && line_width_ == o.line_width && antialias_ == o.antialias &&
                      shade_outside_ == o.shade_outside && rim_line_ == o.rim_line;
    if (same) return rows_.data();
    rows_.resize(h);  // (within the room reserved: no allocation)
    for (std::size_t y = 0; y < h; ++y) {
        const Row at = row_of(circle, o, static_cast<int>(y), c.width());
        BackdropRow& kept = rows_[y];
        if (!narrow(at.in, kept.in) || !narrow(at.outer, kept.outer) || !narrow(at.inner, kept.inner)) {
            rows_.clear();
            return nullptr;
        }
    }
    circle_ = circle, width_ = c.width(), line_width_ = o.line_width;
    antialias_ = o.antialias, shade_outside_ = o.shade_outside, rim_line_ = o.rim_line;
    return rows_.data();
}

void draw_backdrop_rows(const Canvas& c, const LimitCircle& circle, const DrawOptions& o, int y0, int y1,
                        const BackdropRow* rows) {
    const int w = c.width(), bpp = c.format().bytes_per_pixel();
    const detail::SpanPattern bg(c.format().pack(o.background), bpp), out(c.format().pack(o.outside), bpp);
    uint8_t rim[4];  // one pixel of the circle's colour
    {
        const uint32_t word = c.format().pack(o.rim);
        std::memcpy(rim, &word, 4);
    }
    const double half = o.line_width / (2.0 * kSub);  // the circle line's half width, px
    y0 = std::max(y0, 0), y1 = std::min(y1, c.height());
    for (int y = y0; y < y1; ++y) {
        uint8_t* row = c.row(y);
        const Row at = rows ? Row{widen(rows[y].in), widen(rows[y].outer), widen(rows[y].inner)} : row_of(circle, o, y, w);
        if (o.shade_outside) {
            const int a = std::clamp(at.in.first, 0, w), b = std::clamp(at.in.last + 1, 0, w);
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
        const ColumnSpan outer = at.outer, inner = at.inner;
        if (outer.first > outer.last) continue;  // (no line in this row)
        if (o.antialias) {  // the pixels within half + 1/2 of the circle, blended
            if (inner.first > inner.last) {
                blend_circle_row(c, circle, half, o.rim, y, outer.first, outer.last);
            } else {
                blend_circle_row(c, circle, half, o.rim, y, outer.first, inner.first - 1);
                blend_circle_row(c, circle, half, o.rim, y, inner.last + 1, outer.last);
            }
            continue;
        }
        // The pixels whose centres lie within half the line's width of the circle: inside the
        // circle of radius r + half and not inside the one of radius r - half.
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
