// Where a body's curve goes on its way to the rasteriser: the engine's outline
// (geometry/engine.hpp) gives each point of it as a Spot (its sub-pixel place, whether the
// projection shows it, whether it lies within the clip circle) and the chords between them;
// ClipSink clips them to the clip circle into one polyline, kBreak where it leaves the circle or
// the projection cannot show it.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "render/raster.hpp"
#include "render/screen_points.hpp"

namespace noneuclid::render {

using geo::Spot;

// Writes a body's polyline: its first point (start), then each chord to the next point
// (chord), clipped to the clip circle: a chord that leaves the circle ends at it, and the
// polyline breaks there (kBreak); one that enters starts at it. A point the projection does not
// show breaks the polyline too. No entry is written twice in a row as a break, and the first
// entry is never one.
class ClipSink {
public:
    ClipSink(double ox, double oy, int64_t clip, SubPoint* out) : ox_(ox), oy_(oy), r_(static_cast<double>(clip)), out_(out) {}
    template <class T>
    ClipSink(const ScreenMap<T>& m, SubPoint* out) : ClipSink(m.ox, m.oy, m.clip, out) {}

    void start(const Spot& p) {
        if (p.in) put(p.at);
    }
    void chord(const Spot& a, const Spot& b) {
        if (a.in && b.in) [[likely]] return put(b.at);
        clipped(a, b);
    }
    // Whether the curve through a, m and b, all three outside the circle, stays outside it: the
    // chord a -> b keeps farther from the circle than twice m's distance from the chord (the
    // curve's greatest departure from its chord, with room to spare).
    [[gnu::noinline]] bool stays_outside(SubPoint a, SubPoint m, SubPoint b) const {
        const double ax = a.x - ox_, ay = a.y - oy_, dx = double(b.x) - a.x, dy = double(b.y) - a.y;
        const double l2 = dx * dx + dy * dy;
        if (!(l2 > 0)) return true;
        const double t = std::fmin(std::fmax(-(ax * dx + ay * dy) / l2, 0.0), 1.0);
        const double near = std::hypot(ax + t * dx, ay + t * dy);
        const double off = std::fabs(dx * (double(m.y) - a.y) - dy * (double(m.x) - a.x)) / std::sqrt(l2);
        return near - 2 * off > r_;
    }
    // Ends the polyline here (the next point starts another).
    void end() {
        if (open_) out_[n_++] = kBreak, open_ = false;
    }
    std::size_t count() const { return n_; }
    SubPoint* out() const { return out_; }

private:
    // chord() where a point is outside the circle.
    [[gnu::noinline]] void clipped(const Spot& a, const Spot& b) {
        if (a.in) {  // leaving
            if (b.shown) put(crossing(a.at, b.at, false));
            return end();
        }
        if (b.in) {  // entering
            if (a.shown) put(crossing(b.at, a.at, false));
            return put(b.at);
        }
        if (a.shown && b.shown) through(a.at, b.at);
    }
    void put(SubPoint p) {
        out_[n_++] = p;
        open_ = true;
    }
    // Where the chord from p to q meets the circle: the first meeting from p (`first`), or for
    // p inside, where it leaves. Solved in double: t = (-b +- sqrt(b^2 - a c)) / a.
    SubPoint crossing(SubPoint p, SubPoint q, bool first) const {
        const double fx = p.x - ox_, fy = p.y - oy_, dx = double(q.x) - p.x, dy = double(q.y) - p.y;
        const double a = dx * dx + dy * dy, b = fx * dx + fy * dy, c = fx * fx + fy * fy - r_ * r_;
        const double disc = std::fmax(b * b - a * c, 0.0), root = std::sqrt(disc);
        double t = a > 0 ? (first ? (-b - root) / a : (-b + root) / a) : 0;
        t = std::fmin(std::fmax(t, 0.0), 1.0);
        return {static_cast<int32_t>(std::lround(p.x + t * dx)), static_cast<int32_t>(std::lround(p.y + t * dy))};
    }
    // A chord with both ends outside: the piece of it inside the circle, if any.
    void through(SubPoint p, SubPoint q) {
        const double fx = p.x - ox_, fy = p.y - oy_, dx = double(q.x) - p.x, dy = double(q.y) - p.y;
        const double a = dx * dx + dy * dy, b = fx * dx + fy * dy, c = fx * fx + fy * fy - r_ * r_;
        if (!(a > 0) || b >= 0 || b <= -a) return;  // the nearest point to the centre is not inside the chord
        if (b * b - a * c <= 0) return;                // the line misses the circle
        put(crossing(p, q, true));
        put(crossing(p, q, false));
        end();
    }

    double ox_, oy_, r_;
    SubPoint* out_;
    std::size_t n_ = 0;
    bool open_ = false;
};

}  // namespace noneuclid::render
