#include "render/fill_rows.hpp"

#include <algorithm>

#include "fixed/division.hpp"
#include "render/screen_points.hpp"
#include "render/texture.hpp"

namespace noneuclid::render {

namespace {

int64_t isqrt(int64_t v) { return v <= 0 ? 0 : static_cast<int64_t>(fx::detail::isqrt64(static_cast<uint64_t>(v))); }
// a - b for coordinates of a polyline, clamped to +-2^22 px (farther is beyond any coverage), so
// that a sum of two products of them fits in 64 bits.
int64_t diff(int64_t a, int64_t b) { return std::clamp<int64_t>(a - b, -(int64_t{1} << 30), int64_t{1} << 30); }
// x on the line through a and b at height y (a.y != b.y), rounded toward zero.
int64_t x_at(SubPoint a, SubPoint b, int64_t y) {
    return a.x + (y - a.y) * (int64_t{b.x} - a.x) / (int64_t{b.y} - a.y);
}

// The polyline's segments (i to i + 1) in the order of their tops, in w.order, for the rows to
// take up in turn (w.active: the segments that reach the current row's strip).
void sort_segments(const FillJob& j, RowWork& w) {
    w.order.clear(), w.active.clear();
    for (std::size_t i = 0; i + 1 < j.count; ++i)
        if (j.points[i].y != kBreak.y && j.points[i + 1].y != kBreak.y) w.order.push_back(static_cast<uint32_t>(i));
    auto top = [&](uint32_t i) { return std::min(j.points[i].y, j.points[i + 1].y); };
    std::sort(w.order.begin(), w.order.end(), [&](uint32_t p, uint32_t q) { return top(p) < top(q); });
}
// The segments within the strip [yc - D, yc + D] into w.active: those whose tops it has reached
// added, those wholly above it dropped (rows come in increasing y).
void activate(const FillJob& j, int64_t yc, RowWork& w, std::size_t& taken) {
    const int64_t D = j.zone;
    while (taken < w.order.size()) {
        const uint32_t i = w.order[taken];
        if (std::min(j.points[i].y, j.points[i + 1].y) > yc + D) break;
        w.active.push_back(i), ++taken;
    }
    std::size_t kept = 0;
    for (uint32_t i : w.active)
        if (std::max(j.points[i].y, j.points[i + 1].y) >= yc - D) w.active[kept++] = i;
    w.active.resize(kept);
}

// The row's crossings and zones (and, anti-aliased, its near segments) into w, from the
// segments w.active holds.
void scan_row(const FillJob& j, int64_t yc, RowWork& w) {
    const int64_t D = j.zone;
    w.crossings.clear(), w.zones.clear(), w.near.clear();
    for (uint32_t i : w.active) {
        const SubPoint a = j.points[i], b = j.points[i + 1];
        const int64_t lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
        if (hi < yc - D || lo > yc + D) continue;
        if ((a.y <= yc) != (b.y <= yc)) w.crossings.push_back(static_cast<int32_t>(x_at(a, b, yc)));
        int64_t x0 = a.x, x1 = b.x;  // the segment's x within rows [yc - D, yc + D]
        if (a.y != b.y) x0 = x_at(a, b, std::max(lo, yc - D)), x1 = x_at(a, b, std::min(hi, yc + D));
        w.zones.push_back({std::min(x0, x1) - D, std::max(x0, x1) + D});
        if (j.aa) {
            const int64_t dx = diff(b.x, a.x), dy = diff(b.y, a.y);
            w.near.push_back({a, b, std::max<int64_t>(1, isqrt(dx * dx + dy * dy))});
        }
    }
    if (j.rim) {  // the circle's points within the strip, and its crossings of the row
        const int64_t d0 = yc - D - j.rim_cy, d1 = yc + D - j.rim_cy, r = j.rim_r;
        const int64_t near = d0 <= 0 && d1 >= 0 ? 0 : std::min(std::abs(d0), std::abs(d1));
        const int64_t far = std::min(r, std::max(std::abs(d0), std::abs(d1)));
        if (near <= r) {
            const int64_t wide = isqrt(r * r - near * near), narrow = isqrt(r * r - far * far);
            w.zones.push_back({j.rim_cx - wide - D, j.rim_cx - narrow + D});
            w.zones.push_back({j.rim_cx + narrow - D, j.rim_cx + wide + D});
        }
        const int64_t dy = yc - j.rim_cy;
        if (std::abs(dy) < r) {
            const int64_t h = isqrt(r * r - dy * dy);
            w.crossings.push_back(static_cast<int32_t>(j.rim_cx - h)), w.crossings.push_back(static_cast<int32_t>(j.rim_cx + h));
        }
    }
    std::sort(w.crossings.begin(), w.crossings.end());
    std::sort(w.zones.begin(), w.zones.end(), [](const RowWork::Zone& p, const RowWork::Zone& q) { return p.from < q.from; });
    std::size_t merged = 0;  // overlapping zones joined, in place
    for (const RowWork::Zone& z : w.zones) {
        if (merged > 0 && z.from <= w.zones[merged - 1].to) w.zones[merged - 1].to = std::max(w.zones[merged - 1].to, z.to);
        else w.zones[merged++] = z;
    }
    w.zones.resize(merged);
}

// The pixels whose centres (x + 1/2, in 1/256 px) lie in [from, to]: [first, last].
int64_t first_pixel(int64_t from) { return -((int64_t{kSub / 2} - from) >> kSubBits); }
int64_t last_pixel(int64_t to) { return (to - kSub / 2) >> kSubBits; }

}  // namespace

void RowWork::reserve(std::size_t segments) {
    order.reserve(segments);
    active.reserve(segments);
    crossings.reserve(segments + 2);
    zones.reserve(segments + 2);
    near.reserve(segments);
}

int fill_coverage(const RowCover& cover, int x, bool inside) {
    const int64_t px = int64_t{x} * kSub + kSub / 2, py = int64_t{cover.y} * kSub + kSub / 2;
    int64_t best = int64_t{1} << 40;  // the distance to the nearest segment, 1/256 px
    for (std::size_t i = 0; i < cover.count; ++i) {
        const FillSegment& s = cover.segments[i];
        const int64_t dx = diff(s.b.x, s.a.x), dy = diff(s.b.y, s.a.y), ex = diff(px, s.a.x), ey = diff(py, s.a.y);
        const int64_t along = dx * ex + dy * ey, len2 = s.length * s.length;
        int64_t d;
        if (along <= 0) d = isqrt(ex * ex + ey * ey);
        else if (along >= len2) d = isqrt((ex - dx) * (ex - dx) + (ey - dy) * (ey - dy));
        else d = std::abs(dx * ey - dy * ex) / s.length;
        best = std::min(best, d);
    }
    if (cover.rim) {
        const int64_t ex = diff(px, cover.rim_cx), ey = diff(py, cover.rim_cy);
        best = std::min(best, std::abs(isqrt(ex * ex + ey * ey) - cover.rim_r));
    }
    const int64_t half = std::min<int64_t>(best, kSub / 2) * 255 / kSub;  // 0 .. 127
    return static_cast<int>(inside ? 128 + half : 127 - half);
}

void fill_rows(const Canvas& c, const FillJob& j, int y0, int y1, RowWork& w) {
    if (!j.on) return;
    y0 = std::max({y0, j.top, 0}), y1 = std::min({y1, j.bottom, c.height()});
    const PixelWriter out{c};
    std::size_t taken = 0;  // segments of w.order taken up
    if (!j.brute) sort_segments(j, w);
    for (int y = y0; y < y1; ++y) {
        // The row's pixels whose centres lie within the shown disc: [lo, hi).
        const int64_t yc = int64_t{y} * kSub + kSub / 2, dc = yc - j.clip_cy;
        if (std::abs(dc) > j.clip_r) continue;
        const int64_t half = isqrt(j.clip_r * j.clip_r - dc * dc);
        const int lo = static_cast<int>(std::clamp<int64_t>(first_pixel(j.clip_cx - half), 0, c.width()));
        const int hi = static_cast<int>(std::clamp<int64_t>(last_pixel(j.clip_cx + half) + 1, lo, c.width()));
        if (j.brute) {
            const int x0 = std::max({j.left, lo}), x1 = std::min(j.right, hi);
            if (x0 < x1) j.test(j.body, c, y, x0, x1, nullptr);
            continue;
        }
        activate(j, yc, w, taken);
        scan_row(j, yc, w);
        const RowCover cover{w.near.data(), w.near.size(), j.rim, j.rim_cx, j.rim_cy, j.rim_r, y};
        std::size_t crossed = 0;  // crossings left of the current place
        int64_t next = INT64_MIN;  // the first pixel after the last zone
        for (const RowWork::Zone& z : w.zones) {
            const int64_t a = first_pixel(z.from), b = last_pixel(z.to);
            if (crossed % 2 == 1 && next != INT64_MIN) {  // between two zones, inside
                const int x0 = static_cast<int>(std::clamp<int64_t>(next, lo, hi));
                const int x1 = static_cast<int>(std::clamp<int64_t>(a, lo, hi));
                if (x0 < x1) {
                    if (j.solid) out.run(y, x0, x1, j.word);
                    else j.span(j.body, c, y, x0, x1);
                }
            }
            const int x0 = static_cast<int>(std::clamp<int64_t>(a, lo, hi));
            const int x1 = static_cast<int>(std::clamp<int64_t>(b + 1, lo, hi));
            if (x0 < x1) j.test(j.body, c, y, x0, x1, j.aa ? &cover : nullptr);
            while (crossed < w.crossings.size() && w.crossings[crossed] <= z.to) ++crossed;
            next = std::max(next, b + 1);
        }
    }
}

}  // namespace noneuclid::render
