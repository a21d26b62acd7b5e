// The earth scene at K = +1 against PROJ (docs/earth.md): every coastline point of
// world/earth_data.hpp, placed as the scene places it (world::earth_polar) and drawn by the
// fixed and double engines in each of the five projections, must land within kWithinPx of PROJ's
// forward projection of the same latitude and longitude on a sphere (+proj=aeqd, stere, gnom,
// ortho, laea with +R=1, the same centre), at the same scale: screen radius = PROJ's radius x
// (half the shorter side) / (the projected radius of the shown disc's edge, written below from
// the projections' formulas). Centres: Greenwich, both poles, points on the antimeridian and
// Sydney (kCentres). And no point PROJ puts well inside the shown disc may be missing from the drawing.
// Zoomed (--view KM), the Earth is the sphere of K = (KM / (pi 6371))^2 and the same holds with
// the shown disc's edge at the angle KM / 6371 (or the projection's cut): zoom by curvature is
// PROJ's map of the Earth at that scale.
// Runs Debian's `proj` (proj-bin, a test dependency only); fails, naming it, without it.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>
#include <vector>

#include "render/body_points.hpp"
#include "world/earth.hpp"
#include "world/earth_data.hpp"
#include "world/world.hpp"

namespace {

using namespace noneuclid;

constexpr double kWithinPx = 0.5;   // the bound: a drawn point from PROJ's
constexpr double kInsidePx = 2.0;   // PROJ's points this far inside the clip circle must be drawn
constexpr double kPi = 3.14159265358979323846;

// A projection: its PROJ name, its radius on the unit sphere at angle a from the centre, and
// the angle where noneuclid cuts the view short of the limit circle (geometry/projection.hpp).
struct ProjRow {
    geo::Projection projection;
    const char* proj;
    double (*radius)(double a);
    double cut;  // radians; pi: none
};
const ProjRow kRows[] = {
    {geo::Projection::azimuthal_equidistant, "aeqd", [](double a) { return a; }, kPi},
    {geo::Projection::stereographic, "stere", [](double a) { return 2 * std::tan(a / 2); }, 2 * kPi / 3},
    {geo::Projection::gnomonic, "gnom", [](double a) { return std::tan(a); }, kPi / 3},
    {geo::Projection::orthographic, "ortho", [](double a) { return std::sin(a); }, kPi / 2},
    {geo::Projection::lambert_equal_area, "laea", [](double a) { return 2 * std::sin(a / 2); }, kPi},
};
// The views: the whole globe (K = 1) and zoomed, km from the centre to the screen's edge.
constexpr double kEarthKm = 6371, kGlobe = kPi * kEarthKm;
const double kViews[] = {kGlobe, 5000, 1000, 100};
struct Centre {
    double lat, lon;
};
// Greenwich, the poles, the antimeridian (the Pacific; Chukotka, where Natural Earth cuts the
// land there) and Sydney.
const Centre kCentres[] = {{51.5, 0}, {90, 0}, {-90, 0}, {0, 180}, {20, -179.5}, {65.5, 180}, {-33.9, 151.2}};
// Zoomed in, where there is land in view.
bool zoom_here(Centre c) { return c.lat == 51.5 || c.lat == 65.5 || c.lat == -33.9; }
struct Size {
    int w, h;
};
const Size kSizes[] = {{800, 480}, {1920, 1080}};

struct Xy {
    bool ok = false;
    double x = 0, y = 0;
};

// PROJ's forward projection of every data point about the centre, on the unit sphere.
std::vector<Xy> run_proj(const char* name, Centre c, const std::string& input) {
    char cmd[512];
    std::snprintf(cmd, sizeof cmd, "proj +proj=%s +R=1 +lat_0=%.10g +lon_0=%.10g -f %%.12f < %s", name, c.lat, c.lon,
                  input.c_str());
    std::vector<Xy> out;
    FILE* p = popen(cmd, "r");
    if (!p) return out;
    char line[256];
    while (std::fgets(line, sizeof line, p)) {
        Xy q;
        q.ok = std::sscanf(line, "%lf %lf", &q.x, &q.y) == 2 && std::isfinite(q.x) && std::isfinite(q.y);
        out.push_back(q);
    }
    pclose(p);
    return out;
}

double lat_of(std::size_t i) { return world::earth_data::kPoints[i][0] * 1e-4; }
double lon_of(std::size_t i) { return world::earth_data::kPoints[i][1] * 1e-4; }

// Each data point as a body of one vertex at its place about the centre (the scene's mapping),
// the earth scene's way: centre at O, the point its local vertex.
// Zoomed, the Earth is the sphere of curvature K, radius 1 / sqrt K: a place at angle a is at
// a / sqrt K (and one past the view is put just outside it: it is not drawn).
world::Scene points_scene(Centre c, double view) {
    world::Scene s;
    s.curvature = (view / kGlobe) * (view / kGlobe);
    s.limit_radius = kPi;
    for (std::size_t i = 0; i < std::size(world::earth_data::kPoints); ++i) {
        const world::EarthPolar q = world::earth_polar(c.lat, c.lon, lat_of(i), lon_of(i));
        world::SceneBody b;
        b.grid = true, b.closed = false;
        b.vertices = {{std::fmin(q.r / std::sqrt(s.curvature), kPi + 0.5), q.theta_deg}};
        s.bodies.push_back(b);
    }
    return s;
}

struct Result {
    double worst = 0;
    long compared = 0, missing = 0;
};

// The drawn point of each body against PROJ's, in engine W.
template <class W>
Result compare(const world::Scene& s, const ProjRow& row, double view, const std::vector<Xy>& proj, Size size) {
    using T = typename W::scalar;
    W world(s);
    std::vector<typename W::engine::Cache> caches;
    render::make_shape_caches(world, caches);
    render::DrawOptions o;
    o.projection = row.projection;
    const geo::ScreenMap<T> m = geo::ScreenMap<T>::of(size.w, size.h, world.K, T(kPi), row.projection);
    const double rim = row.radius(std::fmin(view / kEarthKm, row.cut));
    const double scale = std::fmin(size.w, size.h) / 2.0 / rim, clip = static_cast<double>(m.clip) / geo::kSub;
    Result r;
    // (The scene's own bodies, one point each: the world's instruments follow them, off.)
    for (std::size_t i = 0; i < s.bodies.size() && i < proj.size(); ++i) {
        geo::Polar<T> verts[1];
        geo::Vec3<T> vecs[1];
        geo::SubPoint out[8];
        const std::size_t n = render::body_screen_points(world, world.bodies[i], caches[i], m, o, verts, vecs, out);
        const bool drawn = n == 1 && out[0].x != geo::kBreak.x;
        if (!proj[i].ok) {
            if (drawn) ++r.missing;  // drawn where PROJ has no point (the far hemisphere)
            continue;
        }
        const double px = size.w / 2.0 + scale * proj[i].x, py = size.h / 2.0 - scale * proj[i].y;
        if (!drawn) {
            if (std::hypot(px - size.w / 2.0, py - size.h / 2.0) < clip - kInsidePx) ++r.missing;
            continue;
        }
        const double d = std::hypot(out[0].x / double(geo::kSub) - px, out[0].y / double(geo::kSub) - py);
        r.worst = std::fmax(r.worst, d);
        ++r.compared;
    }
    return r;
}

}  // namespace

int main() {
    if (std::system("command -v proj > /dev/null 2>&1") != 0) {
        std::puts("earth_proj: PROJ's proj is not installed: install Debian's proj-bin (platform/debian/packages.sh's test group)");
        return 1;
    }
    char input[] = "/tmp/noneuclid-earth-proj-XXXXXX";
    const int fd = mkstemp(input);
    if (fd < 0) return std::perror("mkstemp"), 1;
    {
        std::string text;
        char line[64];
        for (std::size_t i = 0; i < std::size(world::earth_data::kPoints); ++i)
            text += (std::snprintf(line, sizeof line, "%.4f %.4f\n", lon_of(i), lat_of(i)), line);
        if (write(fd, text.data(), text.size()) != static_cast<ssize_t>(text.size())) return std::perror("write"), 1;
        close(fd);
    }
    bool ok = true;
    double worst[5][2] = {};
    for (const Centre& c : kCentres) {
        for (double view : kViews) {
            // (Zoomed: three centres, at the kiosk's size.)
            if (view < kGlobe && !zoom_here(c)) continue;
            const world::Scene s = points_scene(c, view);
            for (std::size_t p = 0; p < std::size(kRows); ++p) {
                const ProjRow& row = kRows[p];
                const std::vector<Xy> proj = run_proj(row.proj, c, input);
                if (proj.size() != std::size(world::earth_data::kPoints)) {
                    std::printf("proj +proj=%s gave %zu lines for %zu points\n", row.proj, proj.size(),
                                std::size(world::earth_data::kPoints));
                    ok = false;
                    continue;
                }
                for (const Size& size : kSizes) {
                    if (view < kGlobe && size.w != 800) continue;
                    for (int e = 0; e < 2; ++e) {
                        const Result r = e == 0 ? compare<world::World<fx::fixed>>(s, row, view, proj, size)
                                                : compare<world::World<double>>(s, row, view, proj, size);
                        // (zoomed to 1000 km and less, few of the coarse data's points are in view)
                        const bool pass = r.worst <= kWithinPx && r.missing == 0 && r.compared >= (view >= 5000 ? 100 : 2);
                        worst[p][e] = std::fmax(worst[p][e], r.worst);
                        std::printf("%-5s centre %6.1f,%7.1f view %5.0f km %4dx%-4d %-6s: %5ld points, worst %.4f px, %ld missing%s\n",
                                    row.proj, c.lat, c.lon, view, size.w, size.h, e == 0 ? "fixed" : "double", r.compared,
                                    r.worst, r.missing, pass ? "" : "  FAIL");
                        ok = ok && pass;
                    }
                }
            }
        }
    }
    unlink(input);
    std::printf("worst over the centres and sizes (px), fixed / double:\n");
    for (std::size_t p = 0; p < std::size(kRows); ++p)
        std::printf("  %-5s %.4f / %.4f\n", kRows[p].proj, worst[p][0], worst[p][1]);
    std::printf(ok ? "all within %.1f px\n" : "FAILED: a point farther than %.1f px, or missing\n", kWithinPx);
    return ok ? 0 : 1;
}
