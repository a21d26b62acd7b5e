// Part of the rasteriser (raster.cpp, which alone includes it): anti-aliased and thick lines,
// drawn as a band of the line's width around it, column by column.
#pragma once

#include <cmath>
#include <cstdint>

#include "render/raster.hpp"
#include "render/raster_plot.hpp"

namespace noneuclid::render {
namespace {

// The band of the given width around the line, per column: exact coverage (anti-aliased) or
// the pixels whose centre it covers (thick aliased).
template <class P>
void wide_line(P& p, int64_t u0, int64_t v0, int64_t u1, int64_t v1, int32_t width, bool aa, bool cut) {
    const double du = static_cast<double>(u1 - u0), dv = static_cast<double>(v1 - v0);
    const Columns col = columns<int64_t>(u0, u1);
    if (col.count == 0) return;
    // Rows across the band are checked one by one below: [rlo, rhi) are the rows (or columns)
    // that may be written across it.
    const int64_t rlo = p.swap ? 0 : p.row0, rhi = p.swap ? p.sink.width() : p.row1;
    // Per column, in integers with 32 fractional bits of a pixel: the band's centre v (stepped by
    // the slope) and its minor-axis extent h = width * length / major (set up once per line).
    constexpr double kQ = 4294967296.0;
    const double slope = dv / du;
    const int64_t h = static_cast<int64_t>((width / double(kSub)) * std::sqrt(du * du + dv * dv) / std::fabs(du) * kQ);
    const double uc0 = static_cast<double>(col.first * kSub + kSub / 2);
    int64_t v = static_cast<int64_t>((static_cast<double>(v0) + (uc0 - static_cast<double>(u0)) * slope) / kSub * kQ);
    const int64_t dv_col = static_cast<int64_t>(slope * static_cast<double>(col.step) * kQ);
    constexpr int64_t one = int64_t{1} << 32;
    // In a row band, only the columns that can reach it: y major, the columns are rows; x major,
    // the columns whose centre v is within the band widened by h / 2 and a pixel (v moves by
    // dv_col per column, exactly: v + k dv_col is what k additions give). A column more than
    // needed costs nothing but time: the rows are checked one by one.
    int64_t kmin = 0, kmax = col.count - 1;
    if (cut) {
        if (p.swap) {
            if (col.step > 0)
                kmin = p.row0 - col.first, kmax = p.row1 - 1 - col.first;
            else
                kmin = col.first - p.row1 + 1, kmax = col.first - p.row0;
        } else {
            const int64_t L = (p.row0 - 1) * one - h / 2, H = (p.row1 + 1) * one + h / 2;  // L < v < H
            if (dv_col > 0)
                kmin = floor_div(L - v, dv_col), kmax = ceil_div(H - v, dv_col);
            else if (dv_col < 0)
                kmin = floor_div(v - H, -dv_col), kmax = ceil_div(v - L, -dv_col);
        }
        if (kmin < 0) kmin = 0;
        if (kmax > col.count - 1) kmax = col.count - 1;
    }
    int64_t u = col.first + kmin * col.step;
    v += kmin * dv_col;
    for (int64_t k = kmin; k <= kmax; ++k, u += col.step, v += dv_col) {
        const int64_t lo = v - h / 2, hi = v + h / 2;
        int64_t r = lo >> 32;
        if (aa) {
            if (r < rlo) r = rlo;
            for (; r < rhi && (r << 32) < hi; ++r) {
                const int64_t top = (r << 32) > lo ? (r << 32) : lo, bottom = ((r + 1) << 32) < hi ? ((r + 1) << 32) : hi;
                const int alpha = static_cast<int>(((bottom - top) * 255 + (one >> 1)) >> 32);
                if (alpha > 0) p.blend(u, r, alpha);
            }
        } else {  // rows whose centre r + 1/2 lies in [lo, hi)
            const int64_t first = (lo - (one >> 1) + one - 1) >> 32, last = ((hi - (one >> 1) + one - 1) >> 32) - 1;
            for (r = first > rlo ? first : rlo; r <= last && r < rhi; ++r) p.opaque(u, r);
        }
    }
}

// A thick aliased line as its capsule: the pixels whose centre lies within width / 2 of the
// segment (not only of its line between the end columns), so that the segments of a polyline
// overlap at every join, however sharp the turn, with no notch. Per column, the capsule (convex)
// meets the column's centre line in one interval: the union of the strip about the line within
// the segment's perpendicular slab and the two end discs. In double, in 1/256 px.
template <class P>
void capsule_line(P& p, int64_t u0, int64_t v0, int64_t u1, int64_t v1, int32_t width) {
    const double r = width / 2.0, a = static_cast<double>(u0), b = static_cast<double>(v0);
    const double du = static_cast<double>(u1 - u0), dv = static_cast<double>(v1 - v0);
    const double L2 = du * du + dv * dv, half = r * std::sqrt(L2) / std::fabs(du);  // du != 0: u is the major axis
    const int64_t lo_u = (u0 < u1 ? u0 : u1) - width, hi_u = (u0 < u1 ? u1 : u0) + width;
    int64_t first = ceil_sub<int64_t>(lo_u - kSub / 2), last = floor_sub<int64_t>(hi_u - kSub / 2);
    const int64_t along = p.swap ? p.row1 : p.sink.width(), along0 = p.swap ? p.row0 : 0;  // the columns on the canvas
    if (first < along0) first = along0;
    if (last > along - 1) last = along - 1;
    const int64_t rlo = p.swap ? 0 : p.row0, rhi = p.swap ? p.sink.width() : p.row1;
    for (int64_t u = first; u <= last; ++u) {
        const double uc = static_cast<double>(u * kSub + kSub / 2), x = uc - a;
        double lo = INFINITY, hi = -INFINITY;
        auto disc = [&](double eu, double ev) {
            const double d = uc - eu;
            if (std::fabs(d) >= r) return;
            const double s = std::sqrt(r * r - d * d);
            lo = std::fmin(lo, ev - s), hi = std::fmax(hi, ev + s);
        };
        disc(a, b), disc(static_cast<double>(u1), static_cast<double>(v1));
        // The strip within width / 2 of the line, cut to the slab 0 <= (P - A).d <= L^2.
        const double vline = b + x * dv / du;
        double slo = vline - half, shi = vline + half;
        if (dv != 0) {
            const double e0 = b - du * x / dv, e1 = b + (L2 - du * x) / dv;
            slo = std::fmax(slo, std::fmin(e0, e1)), shi = std::fmin(shi, std::fmax(e0, e1));
        } else if (x * du < 0 || x * du > L2) {
            shi = -INFINITY;
        }
        if (slo < shi) lo = std::fmin(lo, slo), hi = std::fmax(hi, shi);
        if (!(lo < hi)) continue;
        // Rows whose centre r + 1/2 lies in [lo, hi).
        int64_t row = static_cast<int64_t>(std::ceil((lo - kSub / 2) / kSub));
        const int64_t end = static_cast<int64_t>(std::ceil((hi - kSub / 2) / kSub));  // exclusive
        for (row = row > rlo ? row : rlo; row < end && row < rhi; ++row) p.opaque(u, row);
    }
}

}  // namespace
}  // namespace noneuclid::render
