// Drawing an uneven world (uneven/world.hpp, docs/uneven.md) in one of its two views:
//
//  - the chart view (geo::Projection::stereographic): the chart itself, scaled as the
//    stereographic view of the world of constant K, which it is exactly when there are no
//    bumps. Behind the grid, the curvature K(x) as a colour field: blue where it is negative,
//    red where positive, the stronger the deeper.
//  - the inhabitant's view (any other projection; the HUD names it): what a person standing at
//    O sees, the paper's azimuthal equidistant view, built from a fan of geodesics leaving O: the
//    pixel at distance s from the centre in direction a shows the chart point exp_O(s, a). A
//    body behind a mass is reached by more than one geodesic from O, and is seen more than once.
//
// Bodies: each point of a body's outline is the exponential map from its centre of the point's
// local polar coordinates (rho, phi), traced by RK4 in steps of kDrawStep world units; an edge's
// points are those of the geodesic between its two vertices in the world of constant K, in the
// body's local coordinates, so that with no bumps every edge is the world's geodesic. Points
// traced along one direction (a grid line's) share their trace. The instruments' triangles
// (uneven/triangle.hpp) are drawn over the bodies, their sides as the world traced them.
//
// What is cached, and recomputed only when the metric changes (a new K or gain) or the canvas
// does: the backdrop with the colour field, in the chart; the inhabitant's view's table of
// which chart pixel each pixel shows (from a fan of kFanRays geodesics, kFanSamples points along
// each, interpolated between them); the outlines of the bodies that never move (grid lines).
// The inhabitant's view is drawn as the chart into a canvas of the same size and format, then
// each pixel copied from where the table says: lines keep the chart's width in pixels, so they
// are drawn two pixels wide there. Memory: every buffer is sized by prepare() and on the first
// frame of a canvas size; a frame allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "render/canvas.hpp"
#include "render/draw_options.hpp"
#include "uneven/world.hpp"

namespace noneuclid::uneven {

inline constexpr double kDrawStep = 1.0 / 32;  // world units
inline constexpr int kFanRays = 360, kFanSamples = 192;

// Whether projection p shows the chart (else the inhabitant's view).
inline bool is_chart_view(geo::Projection p) { return p == geo::Projection::stereographic; }

// The colour the field gives curvature k over the background `bg`.
render::Rgb field_color(double k, render::Rgb bg);

class Drawing {
public:
    void prepare(const World& w);
    void draw(const render::Canvas& c, const World& w, const render::DrawOptions& o, bool backdrop);

    // The chart point the inhabitant's view shows at distance s from O in direction a (the
    // fan, interpolated), for tests; valid after a frame of that view.
    Vec2 fan_point(double s, double a) const;
    double fan_reach(double a) const;  // how far the view reaches in direction a
    // Body i's outline as the last frame drew it (sub-pixels, geo::kBreak between runs).
    const std::vector<geo::SubPoint>& outline(std::size_t i) const { return bodies_[i].points; }

private:
    struct BodyCache {
        std::vector<geo::SubPoint> points;
        std::size_t count = 0;
        uint32_t version = 0;  // the metric's, +1 (0: none)
        int width = 0, height = 0, disc = 0;
    };
    struct Key {  // what the backdrop depends on
        int width = 0, height = 0, disc = 0;
        uint32_t version = 0;
        render::PixelFormat format;
        render::Rgb background, outside, rim;
        bool rim_line = true, shade = true, antialias = false;
        int32_t line_width = 0;
        bool operator==(const Key& o) const;
    };
    void draw_chart(const render::Canvas& c, const World& w, const render::DrawOptions& o, bool backdrop);
    void chart_backdrop(const render::Canvas& c, const World& w, const render::DrawOptions& o);
    void body_outline(const World& w, std::size_t i, const geo::ScreenMap<double>& m);
    void draw_triangles(const render::Canvas& c, const World& w, const render::DrawOptions& o, const geo::ScreenMap<double>& m);
    Vec2 trace(const Metric& metric, Vec2 from, double dir, double rho);
    void build_fan(const World& w);
    void build_table(const World& w, int width, int height, int disc);
    template <int B>
    void warp(const render::Canvas& c, render::Rgb outside);

    std::vector<BodyCache> bodies_;
    std::vector<geo::SubPoint> gauge_points_;  // a triangle's sides (draw_triangles)
    std::vector<Geodesic> ray_;  // the trace along one direction (trace()), kDrawStep apart
    double ray_dir_ = 0;
    Vec2 ray_from_;
    std::vector<uint8_t> field_;  // the chart's backdrop with the colour field, rows packed
    std::vector<double> grid_;    // the curvature at every kFieldBlock-th pixel (chart_backdrop)
    Key field_key_;
    std::vector<Vec2> fan_;         // kFanRays x (kFanSamples + 1) chart points
    std::vector<double> reach_;     // each ray's length to the limit circle
    double fan_step_ = 0;           // world units between samples
    double fan_reach_ = 0;          // the longest reach: the view's radius
    uint32_t fan_version_ = 0;
    std::vector<int32_t> table_;    // each pixel's source pixel in the chart (inhabitant's view)
    Key table_key_;
    std::vector<uint8_t> chart_;    // the inhabitant's view's chart, drawn first
};

}  // namespace noneuclid::uneven
