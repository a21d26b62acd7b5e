// A scene file's [[solid]] tables (docs/file-formats.md, "Three-dimensional scenes"): they make
// the scene three-dimensional (src/space). Used by scene_file.cpp.
#pragma once

#include "files/toml_reader.hpp"
#include "world/scene.hpp"

namespace noneuclid::files {

// Reads root's [[solid]] tables into s.solids and marks s three-dimensional; throws tomlr::Bad
// on a bad one, or when the scene also has what only the plane has ([[body]], [[bump]], [game],
// [[measure]], a backdrop, [[grid]]). Nothing when there are none.
void read_solids(const toml::table& root, world::Scene& s);

}  // namespace noneuclid::files
