// The paper's figures as the program draws them: one table, used by `noneuclid demo`, the
// golden-image tests (tests/render/test_golden.cpp), the within-one-pixel check of the figures
// (tests/render/test_curves.cpp) and tests/golden/regenerate.sh (which runs the demo with the
// reference engine at the goldens' size). A figure is one picture of one to three panels side
// by side, each its scene run at its own K and labelled with it, in its projection.
#pragma once

#include "geometry/projection.hpp"

namespace noneuclid::app {

struct Figure {
    const char* name;         // the PNG's name, without .png
    const char* scene;        // a built-in scene
    long frames;              // steps of 1/60 s
    long timelapse = 0;       // 0: the last frame; else every EVERY-th frame's bodies laid over
    bool aa = false;          // anti-aliased lines
    bool hud = false;         // the demo draws the HUD over it
    int width = 480, height = 480;  // one panel's size, the demo's unless --size
    const char* what = "";    // for the demo's summary
    int panels = 1;           // side by side
    double K[3] = {};         // each panel's curvature, unless own_K
    bool own_K = false;       // one panel at the scene's own K (and no label of it)
    long grid_trail = 0;      // and every this-many-th frame's grid over the earlier ones (0: none)
    const char* label = nullptr;  // the panel's label instead of "K = ..."
    geo::Projection projection = geo::Projection::azimuthal_equidistant;
    double centre_lat = 51.5, centre_lon = 0;  // the earth scene's centre (world/earth.hpp)
    bool no_ship = false;     // without the scene's ship (figure 3: the paper's map has none)
};

extern const Figure kFigures[];
extern const int kFigureCount;

// A panel's label: the figure's own, else "K = +1", "K = 0", "K = -1" (K rounded to 2 digits);
// empty for a figure at its scene's own K without a label.
void figure_label(const Figure& f, int panel, char* out, int size);

}  // namespace noneuclid::app
