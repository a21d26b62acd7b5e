// The earth scene's drawn coastlines against PROJ on Natural Earth's original data
// (docs/earth.md#checked-against-proj): the picture `noneuclid render --scene earth --centre C
// --curvature 1 --projection P --size WxH --no-hud --frames 0` draws (rendered here through the
// same code: the options, load_scene, render_picture), at three sizes, five projections and five
// centres, in the fixed and the double engine. Every point of world/earth_data.hpp that PROJ
// (`proj +proj=aeqd|stere|gnom|ortho|laea +R=1`, the same centre) puts inside the shown disc,
// not within 2% of its rim, must lie near a pixel of the coast's colour: the distance from
// PROJ's point, mapped to the screen by this test's own formulas, to the nearest such pixel's
// centre is at most kP99Px at the 99th percentile and kMedianPx at the median, in every case.
// The lines are simplified for the view being drawn; this is what sees it if they are not.
// Zoomed (--view KM) the same holds on the sphere of that curvature (two views over London).
// Runs Debian's `proj` (proj-bin, a test dependency only); fails, naming it, without it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>
#include <vector>

#include "app/options.hpp"
#include "app/picture.hpp"
#include "app/script.hpp"
#include "app/setup.hpp"
#include "render/font.hpp"
#include "world/earth_data.hpp"

namespace {

using namespace noneuclid;

constexpr double kP99Px = 1.0, kMedianPx = 0.5;  // the bounds
constexpr double kRimMargin = 0.02;              // points this close to the rim are not compared
constexpr double kSearchPx = 8;                  // farther than this from any coast pixel: kSearchPx
constexpr double kPi = 3.14159265358979323846, kEarthKm = 6371;

// A projection: its name for --projection and for PROJ, its radius on the unit sphere at angle a
// from the centre, and the angle where noneuclid's view of the sphere ends (geometry/projection.hpp).
struct ProjRow {
    const char* name;
    const char* proj;
    double (*radius)(double a);
    double cut;
};
const ProjRow kRows[] = {
    {"equidistant", "aeqd", [](double a) { return a; }, kPi},
    {"stereographic", "stere", [](double a) { return 2 * std::tan(a / 2); }, 2 * kPi / 3},
    {"gnomonic", "gnom", [](double a) { return std::tan(a); }, kPi / 3},
    {"orthographic", "ortho", [](double a) { return std::sin(a); }, kPi / 2},
    {"lambert", "laea", [](double a) { return 2 * std::sin(a / 2); }, kPi},
};
struct Centre {
    const char* name;
    double lat, lon;
};
const Centre kCentres[] = {{"London", 51.5, 0}, {"0,90E", 0, 90}, {"North Pole", 90, 0}, {"Sydney", -33.9, 151.2},
                           {"antimeridian", 0, 180}};
struct Size {
    int w, h;
};
const Size kSizes[] = {{800, 480}, {800, 800}, {1920, 1080}};
// The views: the whole globe (0), and zoomed over London (km from the centre to the screen's edge).
const double kZooms[] = {5000, 1500};

struct Xy {
    bool ok = false;
    double x = 0, y = 0;
};

// PROJ's forward projection of every data point (the file `input`) about the centre, R = 1.
std::vector<Xy> run_proj(const char* name, const Centre& c, const std::string& input) {
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

// The options `noneuclid render` takes from this command line.
app::Options options_of(std::vector<std::string> words) {
    words.insert(words.begin(), "noneuclid-render");
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    app::Script script;
    return app::layered_options(static_cast<int>(argv.size()), argv.data(), 1, app::Command::render, script);
}

struct Figures {
    long compared = 0;
    double median = 0, p99 = 0, worst = 0;
};

// The picture's coast pixels against PROJ's points; view_km 0: the globe.
Figures compare(const app::Picture& pic, const ProjRow& row, double view_km, const std::vector<Xy>& proj) {
    const render::Canvas& c = pic.canvas;
    const uint32_t coast = c.format().pack({130, 215, 150});
    const int w = c.width(), h = c.height();
    const double angle = view_km > 0 ? view_km / kEarthKm : kPi;
    const double rim = std::min(w, h) / 2.0, scale = rim / row.radius(std::fmin(angle, row.cut));
    std::vector<double> d;
    for (const Xy& q : proj) {
        if (!q.ok) continue;
        const double x = w / 2.0 + scale * q.x, y = h / 2.0 - scale * q.y;
        if (std::hypot(x - w / 2.0, y - h / 2.0) >= (1 - kRimMargin) * rim) continue;
        double best = kSearchPx;
        const int r = static_cast<int>(kSearchPx) + 1;
        for (int j = static_cast<int>(std::floor(y)) - r; j <= static_cast<int>(std::floor(y)) + r; ++j)
            for (int i = static_cast<int>(std::floor(x)) - r; i <= static_cast<int>(std::floor(x)) + r; ++i)
                if (c.contains(i, j) && c.get_word(i, j) == coast) best = std::fmin(best, std::hypot(i + 0.5 - x, j + 0.5 - y));
        d.push_back(best);
    }
    Figures f;
    f.compared = static_cast<long>(d.size());
    if (d.empty()) return f;
    std::sort(d.begin(), d.end());
    f.median = d[d.size() / 2];
    f.p99 = d[std::min(d.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(d.size()))) - 1)];
    f.worst = d.back();
    return f;
}

}  // namespace

int main() {
    if (std::system("command -v proj > /dev/null 2>&1") != 0) {
        std::puts("earth_pixels: PROJ's proj is not installed: install Debian's proj-bin (platform/debian/packages.sh's test group)");
        return 1;
    }
    char input[] = "/tmp/noneuclid-earth-pixels-XXXXXX";
    const int fd = mkstemp(input);
    if (fd < 0) return std::perror("mkstemp"), 1;
    {
        std::string text;
        char line[64];
        for (const auto& p : world::earth_data::kPoints)
            text += (std::snprintf(line, sizeof line, "%.4f %.4f\n", p[1] * 1e-4, p[0] * 1e-4), line);
        if (write(fd, text.data(), text.size()) != static_cast<ssize_t>(text.size())) return std::perror("write"), 1;
        close(fd);
    }
    bool ok = true;
    double most_p99 = 0, most_median = 0;
    std::printf("%-12s %-13s %-9s %-6s %5s %7s %7s %7s\n", "centre", "projection", "size", "engine", "pts", "median", "p99",
                "worst");
    auto one = [&](const Centre& c, double view_km, const ProjRow& row, const std::vector<Xy>& proj, const Size& size,
                   const char* engine) {
        char centre[64], dims[32], view[32];
        std::snprintf(centre, sizeof centre, "%.10g,%.10g", c.lat, c.lon);
        std::snprintf(dims, sizeof dims, "%dx%d", size.w, size.h);
        std::snprintf(view, sizeof view, "%g", view_km);
        std::vector<std::string> words = {"--scene", "earth", "--centre", centre, "--projection", row.name, "--size", dims,
                                          "--no-hud", "--frames", "0", "--engine", engine, "--format", "xrgb8888"};
        if (view_km > 0) words.insert(words.end(), {"--view", view});
        else words.insert(words.end(), {"--curvature", "1"});
        const app::Options o = options_of(words);
        app::Picture pic;
        app::render_picture(o, app::load_scene(o), nullptr, render::builtin_font(), pic);
        const Figures f = compare(pic, row, view_km, proj);
        const bool pass = f.compared >= 20 && f.p99 <= kP99Px && f.median <= kMedianPx;
        ok = ok && pass;
        most_p99 = std::fmax(most_p99, f.p99), most_median = std::fmax(most_median, f.median);
        std::printf("%-12s %-13s %-9s %-6s %5ld %7.3f %7.3f %7.3f%s%s\n", c.name, row.name, dims, engine, f.compared, f.median,
                    f.p99, f.worst, view_km > 0 ? (std::string("  view ") + view + " km").c_str() : "", pass ? "" : "  FAIL");
        std::fflush(stdout);
    };
    for (const Centre& c : kCentres)
        for (const ProjRow& row : kRows) {
            const std::vector<Xy> proj = run_proj(row.proj, c, input);
            if (proj.size() != std::size(world::earth_data::kPoints)) {
                std::printf("proj +proj=%s gave %zu lines for %zu points\n", row.proj, proj.size(),
                            std::size(world::earth_data::kPoints));
                ok = false;
                continue;
            }
            for (const Size& size : kSizes)
                for (const char* engine : {"fixed", "double"}) one(c, 0, row, proj, size, engine);
            if (c.lat == 51.5)  // zoomed over London, at the kiosk's size
                for (double km : kZooms)
                    for (const char* engine : {"fixed", "double"}) one(c, km, row, proj, kSizes[0], engine);
        }
    unlink(input);
    std::printf("largest median %.3f px (bound %.1f), largest 99th percentile %.3f px (bound %.1f)\n", most_median, kMedianPx,
                most_p99, kP99Px);
    std::puts(ok ? "every case within the bounds" : "FAILED: a case past a bound (FAIL above)");
    return ok ? 0 : 1;
}
