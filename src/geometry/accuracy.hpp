// Accuracy of the geometry engines where it shows: on the screen. Shared by
// `noneuclid accuracy` (prints) and tests/geometry (asserts), like fixed/accuracy.hpp.
//
// The screen is a 1080-px-high disk: the limit radius R = pi maps to 540 px through the
// azimuthal equidistant projection (172 px per world unit). A scene of random bodies (centres
// inside the limit circle, 3-6 vertices each at 0.02-0.6 from the centre, edges tessellated at
// level 8) is solved for every K of a sweep over [-1, 1] by each engine and by the reference
// model; the distance in px between an engine's point and the reference's (or the double
// engine's) is the error. Points within 2% of the rim are left out where K > 0: there the
// rim is the antipode, where two points a hair apart land on opposite sides of the screen.
// Rows "near the antipode" sample the same population densely where K is near 1 and the
// centres far out, where the view magnifies the fixed engine's error most.
#pragma once

#include <cstdint>

namespace noneuclid::geo {

struct ScreenErrorRow {
    const char* engine;    // "fixed", "float", "double", "paper", ...
    const char* against;   // "double" or "reference"
    const char* what;      // "vertices", "edge points", ...
    const char* where;     // the K and geometry swept
    long samples;
    long nonfinite;        // NaN or infinite results (counted, not in the statistics)
    double max_px, p50_px, p99_px, p999_px;
    double at_K, at_r;     // where the maximum occurs
    double bound_px;       // asserted (0 = reported only)
    bool pass;
};

struct ContinuityRow {
    const char* engine;
    const char* what;      // which K values are compared
    double max_px;         // largest screen movement of any point between them
    double bound_px;       // asserted (0 = reported only)
    bool pass;
};

// Relative error of the distance between two points a short way apart, where acos of a law
// of cosines near 1 loses half the digits.
struct ShortDistanceRow {
    const char* engine;
    double length;         // the distance measured
    double max_rel;        // max |got - reference| / length over K in {-1, -0.5, -0.02, 0.02, 0.5, 1}
    long nonfinite;
};

struct GeometryReportOptions {
    uint64_t seed = 20190101;
    int bodies = 40;       // per K
    int k_steps = 200;     // K = -1 + 2 i / k_steps
    bool antipode_only = false;  // measure_screen_error: the rows near the antipode alone
};

int screen_error_row_count();
int continuity_row_count();
// Fill up to `capacity` rows; return how many were filled.
int measure_screen_error(const GeometryReportOptions& o, ScreenErrorRow* rows, int capacity);
int measure_continuity(const GeometryReportOptions& o, ContinuityRow* rows, int capacity);
int short_distance_row_count();
int measure_short_distance(const GeometryReportOptions& o, ShortDistanceRow* rows, int capacity);

}  // namespace noneuclid::geo
