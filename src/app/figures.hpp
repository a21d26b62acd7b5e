// The paper's figures as the program draws them: one table, used by `noneuclid demo`, the
// golden-image tests (tests/render/test_golden.cpp) and tests/golden/regenerate.sh (which runs
// the demo with the reference engine at the goldens' size).
#pragma once

namespace noneuclid::app {

struct Figure {
    const char* name;   // the PNG's name, without .png
    const char* scene;  // a built-in scene
    long frames;        // steps of 1/60 s
    long timelapse;     // 0: the last frame; else every EVERY-th frame's bodies laid over
    bool aa;            // anti-aliased lines
    bool hud;           // the demo draws the HUD over it
    int width, height;  // the demo's size unless --size
    const char* what;   // for the demo's summary
};

extern const Figure kFigures[];
extern const int kFigureCount;

}  // namespace noneuclid::app
