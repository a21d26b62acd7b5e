#include "app/figures.hpp"

#include <cstdio>

namespace noneuclid::app {

// Figure 3 is the paper's picture of the Earth (its outlook's cartography): the earth scene's
// eastern hemisphere at K = +1, seen from 5 degrees north of the equator so that no meridian of
// the graticule lies on the limb, where the view's cut would decide each pixel by rounding. Figures 14-16 at K = +1 and -1 as the paper shows them; figure 17 from K = -1 to +1 in 5 s
// (the scene's sweep), its grid laid down at each sampled K.
const Figure kFigures[] = {
    {.name = "kiosk", .scene = "kiosk", .frames = 60, .aa = true, .hud = true, .width = 800, .height = 480,
     .what = "the kiosk's picture", .own_K = true},
    {.name = "fig1", .scene = "fig1", .frames = 120, .what = "figure 1 (a, b, c): the bodies at K = +1, 0 and -1",
     .panels = 3, .K = {1, 0, -1}},
    {.name = "fig2", .scene = "fig2", .frames = 0,
     .what = "figure 2: lines that start parallel meet at K = +1, stay apart at 0, fly apart at -1", .panels = 3,
     .K = {1, 0, -1}},
    {.name = "fig3", .scene = "earth", .frames = 1,
     .what = "figure 3: the Earth's eastern hemisphere, orthographic (the earth scene about 5 N, 90 E)", .own_K = true,
     .label = "K = +1, orthographic", .projection = geo::Projection::orthographic, .centre_lat = 5, .centre_lon = 90,
     .no_ship = true},
    {.name = "fig4", .scene = "fig4", .frames = 0, .aa = true,
     .what = "figure 4: a {7,3} tiling in the Poincare disc (the stereographic view at K = -1)", .K = {-1},
     .label = "{7,3}, K = -1, stereographic", .projection = geo::Projection::stereographic},
    {.name = "fig14", .scene = "fig14", .frames = 600, .timelapse = 40,
     .what = "figure 14: a time-lapse along the geodesic orthogonal to the radius, at K = +1 and -1", .panels = 2,
     .K = {1, -1}},
    {.name = "fig15", .scene = "fig15", .frames = 600, .timelapse = 40,
     .what = "figure 15: the same start, heading 45 degrees, at K = +1 and -1", .panels = 2, .K = {1, -1}},
    {.name = "fig16", .scene = "fig16", .frames = 120, .timelapse = 15,
     .what = "figure 16: the paper's square spinning, at K = +1 and -1", .panels = 2, .K = {1, -1}},
    {.name = "fig17", .scene = "fig17", .frames = 300, .timelapse = 25,
     .what = "figure 17: K swept from -1 to +1 while the body moves, the grid at K = -1, -0.5, 0, 0.5 and 1",
     .own_K = true, .grid_trail = 75, .label = "K = -1 to +1"},
};
const int kFigureCount = static_cast<int>(sizeof kFigures / sizeof kFigures[0]);

void figure_label(const Figure& f, int panel, char* out, int size) {
    if (f.label)
        std::snprintf(out, static_cast<std::size_t>(size), "%s", f.label);
    else if (f.own_K)
        std::snprintf(out, static_cast<std::size_t>(size), "%s", "");
    else if (f.K[panel] == 0)
        std::snprintf(out, static_cast<std::size_t>(size), "%s", "K = 0");
    else
        std::snprintf(out, static_cast<std::size_t>(size), "K = %+.2g", f.K[panel]);
}

}  // namespace noneuclid::app
