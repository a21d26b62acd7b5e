// An instrument's readings as a table for people (`noneuclid measure ... --format table`): a
// line naming the instrument and K, then one row per number: its name, its value rounded as a
// teacher writes it, and its unit (docs/file-formats.md):
//
//   triangle at K = 1
//   side a     1.633  units
//   ...
//   angle A     93.8  °
//   ...
//   area       1.770  units²
//
// Angles to 0.1°; lengths, areas, ratios and curvatures to 0.001 (a fixed number of decimals,
// so that a column of them lines up and a value near 0 reads 0, never 2.5e-14); counts whole.
// A length is in the world's units, the unit in which K = +1 is the sphere of radius 1 and
// K = -1 the hyperbolic plane of curvature radius 1; an area in those units squared and a
// curvature per unit squared. A value that rounds to zero prints without a sign (never -0.0).
// The same readings the JSON carries (files/measure_json.hpp), from the same structs.
#pragma once

#include <string>

#include "geometry/measure.hpp"

namespace noneuclid::files {

// The table's units, and how many decimals each is rounded to.
enum class TableUnit { angle, length, area, curvature, ratio, count };
int table_decimals(TableUnit u);
const char* table_unit_name(TableUnit u);  // "°", "units", "units²", "1/units²", "" for a ratio or count

// `v` rounded to `decimals` places as the table prints it ("0.0", never "-0.0").
std::string table_number(double v, int decimals);

void append_triangle_table(std::string& out, double K, const geo::TriangleReading& t);
void append_circle_table(std::string& out, double K, const geo::CircleReading& c);
void append_parallels_table(std::string& out, double K, const geo::ParallelsReading& p);
void append_polygon_table(std::string& out, double K, const geo::PolygonReading& r);

}  // namespace noneuclid::files
