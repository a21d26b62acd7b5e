// A grid body's screen points kept from frame to frame (body_points.hpp's body_screen_points
// for a cache that keeps them, geo::ShapeCache::Still): a backdrop of lines does not move,
// so a frame in which nothing it is drawn from changed (K, the view, its pose and shape) copies
// the last frame's points instead of drawing them again. And a zoom level's line, shown while
// K = z (world::Body::image_scale), is a similarity of itself from one such frame to the next:
// its every projected radius is F(angle) / sqrt z at K = z, so its screen points are the last
// drawing's scaled about the centre by the ratio of (map scale x image_scale). Those frames
// scale a record of the outline's spots, drawn within a clip circle kRecordReach times the
// view's, and clip them to the view: while the ratio stays within kRecordReach either way (the
// record's chords are then within 0.35 x kRecordReach px of their curves and its vertices
// within kDetailTolerancePx x kRecordReach of the line), then the record is drawn again. The
// first still frame after a zoom draws exactly again.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/engine.hpp"
#include "render/clip_sink.hpp"
#include "render/draw_options.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

inline constexpr double kRecordReach = geo::kDetailReach;
// A zoom's frames draw each line's record again once every kRecordPhases views
// (geo::ShapeCache::Still::record_phase): a zoom's step must then stay under kRecordReach over as many
// frames (the curvature keys move the scale about 1.6% a frame: 8 frames take 1.14).
inline constexpr uint32_t kRecordPhases = 8;
inline constexpr std::size_t kRecordPhaseRoom = 1024;  // (spots: about 500 vertices' worth)

// The room a line's record needs: a spot per start and end, two per chord.
template <class W>
std::size_t record_capacity(const W&, const world::Body<typename W::scalar>& b) {
    return 2 * W::engine::chords(b) + 8;
}

namespace detail {

// The outline's calls recorded (start, chord, end), and stays_outside answered for the
// record's wider circle. Past the room reserved it stops and says so (full).
template <class Record>
class RecordSink {
public:
    RecordSink(double ox, double oy, int64_t clip, std::vector<Record>& rec) : circle_(ox, oy, clip, nullptr), rec_(rec) {
        rec_.clear();
    }
    void start(const Spot& p) { push(p, 0); }
    void chord(const Spot& a, const Spot& b) { push(a, 1), push(b, 2); }
    void end() { push({}, 3); }
    bool stays_outside(SubPoint a, SubPoint m, SubPoint b) const { return circle_.stays_outside(a, m, b); }
    bool full() const { return full_; }

private:
    void push(const Spot& s, uint8_t op) {
        if (rec_.size() == rec_.capacity()) full_ = true;  // (never grows: no allocation)
        if (!full_) rec_.push_back({s, op});
    }
    ClipSink circle_;  // (its stays_outside alone)
    std::vector<Record>& rec_;
    bool full_ = false;
};

// The record's spots scaled by s about the map's centre, clipped to its circle, into out.
template <class Record, class T>
std::size_t replay(const std::vector<Record>& rec, double s, const ScreenMap<T>& m, SubPoint* out) {
    ClipSink sink(m, out);
    // s in 32.32 fixed point: a multiply and a shift a coordinate, exact to 2^-32 of a radius.
    // (Spots are within to_sub's +-2^30 and s within kRecordReach: the product stays below 2^63.)
    const int64_t q = static_cast<int64_t>(std::llround(s * 4294967296.0));
    const int64_t ox = m.ox, oy = m.oy, half = int64_t{1} << 31;
    auto scaled = [&](int32_t v, int64_t o) { return static_cast<int32_t>(o + (((v - o) * q + half) >> 32)); };
    Spot a{};
    for (const Record& r : rec) {
        Spot p = r.s;
        if (s != 1) p.at.x = scaled(p.at.x, ox), p.at.y = scaled(p.at.y, oy);
        p.in = p.shown && m.inside(p.at);
        switch (r.op) {
            case 0: sink.start(p); break;
            case 1: a = p; break;
            case 2: sink.chord(a, p); break;
            default: sink.end(); break;
        }
    }
    return sink.count();
}

}  // namespace detail

// body_screen_points for a body whose cache keeps its points (the header comment).
template <class W>
std::size_t still_screen_points(const W& world, const world::Body<typename W::scalar>& b, typename W::engine::Cache& shape,
                                typename W::engine::Cache::Still& still,
                                const ScreenMap<typename W::scalar>& m, const DrawOptions& o,
                                geo::Polar<typename W::scalar>* verts, geo::Vec3<typename W::scalar>* vecs, SubPoint* out) {
    using Still = typename W::engine::Cache::Still;
    using T = typename W::scalar;
    const typename Still::ScreenKey key{world.K, world.R,    m.scale,        m.cx,   m.cy,
                                        b.facing, b.centre.r, b.centre.theta, m.clip, b.shape,
                                        b.sized,  m.detail ? m.detail->stamp : 0u, o.projection};
    auto keep = [&](std::size_t n, bool scaled) {
        still.screen.assign(out, out + n);  // (within the room reserved: no allocation)
        still.screen_key = key, still.screen_valid = true, still.screen_scaled = scaled;
        return n;
    };
    const bool same = still.screen_valid && still.screen_key == key;
    if (same && !still.screen_scaled) {
        std::copy(still.screen.begin(), still.screen.end(), out);
        return still.screen.size();
    }
    const bool similar = b.image_scale > 0 && still.record.capacity() > 0;
    if (similar && !same && still.record_valid) {  // a zoom's frame: the record scaled, if near enough
        typename Still::ScreenKey pose = key;      // (what a zoom changes left out)
        pose.K = still.record_key.K, pose.scale = still.record_key.scale, pose.clip = still.record_key.clip;
        pose.sized = still.record_key.sized, pose.detail = still.record_key.detail;
        const double s = static_cast<double>(m.scale) * b.image_scale / still.record_scale;
        const bool due = m.detail && m.detail->stamp % kRecordPhases == still.record_phase;
        if (pose == still.record_key && s <= kRecordReach && s >= 1 / kRecordReach && !due)
            return keep(detail::replay(still.record, s, m, out), true);
    }
    if (similar) {  // drawn, recorded within the wider circle, then clipped to the view
        ScreenMap<T> wide = m;
        wide.clip = static_cast<int64_t>(static_cast<double>(m.clip) * kRecordReach);
        detail::RecordSink<typename Still::SpotRecord> rec(wide.ox, wide.oy, wide.clip, still.record);
        W::engine::outline(world.K, b, shape, wide, o.projection, verts, vecs, rec);
        still.record_valid = !rec.full();
        if (still.record_valid) {
            still.record_scale = static_cast<double>(m.scale) * b.image_scale, still.record_key = key;
            return keep(detail::replay(still.record, 1.0, m, out), false);
        }
    }
    ClipSink sink(m, out);
    W::engine::outline(world.K, b, shape, m, o.projection, verts, vecs, sink);
    return keep(sink.count(), false);
}

}  // namespace noneuclid::render
