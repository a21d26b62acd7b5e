// Scene files (the documented example, every error with its place, grids and extensions),
// input files (only a regular file within its limit is read) and a scene file over the world's
// budget (named with its place; the budget itself: tests/world/test_budget.cpp).
#include <gtest/gtest.h>
#include <sys/stat.h>  // mkfifo

#include <filesystem>
#include <fstream>
#include <string>

#include "world/budget.hpp"
#include "files/scene_file.hpp"
#include "files/text_file.hpp"
#include "world/world.hpp"

using namespace noneuclid::world;
using namespace noneuclid::files;

namespace {

// ---- scene files -------------------------------------------------------------------------------

const char* kExample = R"(curvature = -1.0            # K in [-1, 1]
limit_radius = 3.14159      # R in world units
[[body]]
name = "ship"
position = [0.5, 30.0]      # [r, theta deg]
facing = 90.0
velocity = [0.2, 90.0]
spin = 0.0
color = "#ff4040"
closed = true
tessellation = 8
vertices = [[0.1, 0.0], [0.1, 140.0], [0.1, 220.0]]
)";

TEST(SceneFile, TheDocumentedExampleLoads) {
    Scene s;
    SceneError err;
    ASSERT_TRUE(parse_scene(kExample, "ship.toml", s, err)) << err.to_string();
    EXPECT_EQ(s.curvature, -1.0);
    EXPECT_EQ(s.limit_radius, 3.14159);
    ASSERT_EQ(s.bodies.size(), 1u);
    const SceneBody& b = s.bodies[0];
    EXPECT_EQ(b.name, "ship");
    EXPECT_EQ(b.r, 0.5);
    EXPECT_EQ(b.theta_deg, 30.0);
    EXPECT_EQ(b.speed, 0.2);
    EXPECT_EQ(b.color, (Rgb{255, 64, 64}));
    EXPECT_TRUE(b.controlled);  // a body named ship is the one the buttons fly
    ASSERT_EQ(b.vertices.size(), 3u);
    EXPECT_EQ(b.vertices[1].phi_deg, 140.0);
}

struct BadCase {
    const char* text;
    long line, column;
    const char* says;
};
// The text is refused with the message at its line and column, "s.toml:LINE:COLUMN: ...".
void expect_refused(const BadCase& c) {
    Scene s;
    SceneError err;
    EXPECT_FALSE(parse_scene(c.text, "s.toml", s, err)) << c.text;
    EXPECT_EQ(err.line, c.line) << c.text << " -> " << err.to_string();
    EXPECT_EQ(err.column, c.column) << c.text << " -> " << err.to_string();
    EXPECT_NE(err.message.find(c.says), std::string::npos) << c.text << " -> " << err.to_string();
    EXPECT_EQ(err.to_string().rfind("s.toml:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": ", 0), 0u)
        << err.to_string();
}

TEST(SceneFile, EveryErrorNamesItsPlaceWhatWasExpectedAndWhatWasFound) {
    const BadCase cases[] = {
        {"curvature = \n", 1, 13, "not valid TOML"},
        {"curvature = 2.0\n", 1, 13, "'curvature' must be from -1 to 1 (K), found 2"},
        {"curvature = \"flat\"\n", 1, 13, "expected a number for 'curvature' (K), found a string"},
        {"curvture = 0.5\n", 1, 1, "unknown key 'curvture'"},
        {"limit_radius = -1\n", 1, 16, "'limit_radius' must be from"},
        {"presets = \"all\"\n", 1, 11, "expected presets = [K, ...]"},
        {"presets = [0, 3]\n", 1, 15, "'presets' must be from -1 to 1"},
        {"body = 3\n", 1, 8, "expected [[body]] tables, found an integer"},
        {"[[body]]\nname = \"a\"\n", 1, 1, "body 'a': expected 'vertices' = [[rho, phi], ...], found none"},
        {"[[body]]\nname = \"a\"\nvertices = []\n", 3, 12, "with at least one vertex, found an empty array"},
        {"[[body]]\nname = \"a\"\nvertices = [[0.1]]\n", 3, 13, "expected each vertex as [rho, phi in degrees], found an array of 1"},
        {"[[body]]\nname = \"a\"\nvertices = [[-0.1, 0]]\n", 3, 14, "'vertices' must be from 0"},
        {"[[body]]\nname = \"a\"\nvertices = [[0.1, \"x\"]]\n", 3, 19, "expected a number for 'vertices'"},
        {"[[body]]\nname = \"a\"\nposition = [1]\nvertices = [[0.1, 0]]\n", 3, 12, "expected 'position' = [r, theta in degrees], found an array of 1"},
        {"[[body]]\nname = \"a\"\ncolor = \"red\"\nvertices = [[0.1, 0]]\n", 3, 9, "expected a colour \"#rrggbb\" for 'color', found \"red\""},
        {"[[body]]\nname = \"a\"\nclosed = 1\nvertices = [[0.1, 0]]\n", 3, 10, "expected true or false for 'closed', found an integer"},
        {"[[body]]\nname = \"a\"\ntessellation = 0\nvertices = [[0.1, 0]]\n", 3, 16, "'tessellation' must be from 1 to 256"},
        {"[[body]]\nname = \"a\"\ntessellation = 2.5\nvertices = [[0.1, 0]]\n", 3, 16, "expected a whole number for 'tessellation'"},
        {"[[body]]\nname = \"a\"\nfacing = [90]\nvertices = [[0.1, 0]]\n", 3, 10, "expected a number for 'facing' (degrees), found an array"},
        {"[[body]]\nname = \"a\"\nspeed = 1\nvertices = [[0.1, 0]]\n", 3, 1, "body 'a': unknown key 'speed'"},
        {"[[body]]\nname = 7\nvertices = [[0.1, 0]]\n", 2, 8, "expected a string for 'name', found an integer"},
        {"[[grid]]\nkind = \"hex\"\n", 2, 8, "grid: expected kind = \"axes\" or \"radial\", found \"hex\""},
        {"[[grid]]\nspacing = 0\n", 2, 11, "'spacing' must be from"},
        {"backdrop = \"moon\"\n", 1, 12, "expected backdrop = \"earth\" (the only backdrop), found \"moon\""},
        {"centre = [0, 0]\n", 1, 10, "'centre' places the Earth's backdrop: add backdrop = \"earth\""},
        {"backdrop = \"earth\"\ncentre = [100, 0]\n", 2, 11, "'centre' must be from -90 to 90"},
        {"backdrop = \"earth\"\ncentre = [0, 200]\n", 2, 10, "with the longitude from -180 to 180"},
        {"backdrop = \"earth\"\ncentre = 5\n", 2, 10, "expected 'centre' = [latitude, longitude in degrees]"},
        {"backdrop = \"earth\"\n[[grid]]\nkind = \"axes\"\n", 2, 1, "remove the [[grid]] tables, or the backdrop"},
    };
    for (const BadCase& c : cases) expect_refused(c);
    Scene s;
    SceneError err;
    EXPECT_FALSE(load_scene_file("/nonexistent/scene.toml", s, err));
    EXPECT_EQ(err.to_string().rfind("/nonexistent/scene.toml: the scene file: cannot read it", 0), 0u) << err.to_string();
}

// [[solid]] tables: a three-dimensional scene (tests/files/data/solids.toml loads, its solids as
// written), and each mistake in one sentence at its place.
TEST(SceneFile, SolidTablesMakeAThreeDimensionalScene) {
    Scene s;
    SceneError err;
    ASSERT_TRUE(load_scene_file(NONEUCLID_SOURCE_DIR "/tests/files/data/solids.toml", s, err)) << err.to_string();
    EXPECT_TRUE(s.space);
    ASSERT_EQ(s.solids.size(), 2u);
    EXPECT_EQ(s.solids[0].name, "prism");
    EXPECT_EQ(s.solids[0].vertices.size(), 6u);
    EXPECT_EQ(s.solids[0].edges.size(), 9u);
    EXPECT_EQ(s.solids[0].edges[8][0], 2);
    EXPECT_EQ(s.solids[0].spin_deg, 30);
    EXPECT_EQ(s.solids[1].shape, "cube");
    EXPECT_EQ(s.solids[1].size, 0.25);
    const BadCase cases[] = {
        {"[[solid]]\nname = \"a\"\n", 1, 1, "solid 'a': give either shape = \"tetrahedron\""},
        {"[[solid]]\nshape = \"sphere\"\n", 2, 9, "expected shape = \"tetrahedron\", \"cube\""},
        {"[[solid]]\nshape = \"cube\"\nvertices = [[0, 0, 1]]\n", 1, 1, "not both or neither"},
        {"[[solid]]\nvertices = [[0, 0, 1], [1, 0]]\nedges = [[0, 1]]\n", 2, 24, "expected 'vertices' = [x, y, z]"},
        {"[[solid]]\nvertices = [[0, 0, 1], [1, 0, 0]]\nedges = [[0, 2]]\n", 3, 10, "two different vertex numbers from 0 to 1"},
        {"[[solid]]\nvertices = [[0, 0, 1], [1, 0, 0]]\n", 1, 1, "expected 'edges' = [[i, j], ...]"},
        {"[[solid]]\nshape = \"cube\"\nspin_axis = [0, 0, 0]\n", 3, 13, "'spin_axis' must not be [0, 0, 0]"},
        {"[[solid]]\nshape = \"cube\"\nposition = [1000, 0, 0]\n", 3, 13, "'position' must be from -100 to 100"},
        {"limit_radius = 2\n[[solid]]\nshape = \"cube\"\nposition = [2, 1, 0]\n", 4, 12, "must lie within limit_radius"},
        {"[[solid]]\nname = \"a\\\"b\"\nshape = \"cube\"\n", 1, 1, "expected a 'name' of 1 to 40 letters"},
        {"[[body]]\nvertices = [[0.1, 0]]\n[[solid]]\nshape = \"cube\"\n", 1, 1, "'body' belongs to the plane"},
    };
    for (const BadCase& c : cases) expect_refused(c);
}

TEST(SceneFile, GridsAndExtensions) {
    Scene s;
    SceneError err;
    ASSERT_TRUE(parse_scene("presets = [-0.5, 0.5]\nsweep_rate = 0.2\n[[grid]]\nkind = \"radial\"\nlines = 8\n"
                            "[[body]]\nvertices = [[0.1, 0]]\nacceleration = [0.1, 45]\ncontrolled = true\n",
                            "g.toml", s, err))
        << err.to_string();
    EXPECT_EQ(s.presets, (std::vector<double>{-0.5, 0.5}));
    EXPECT_EQ(s.bodies.size(), 9u);
    EXPECT_TRUE(s.bodies[0].grid);
    EXPECT_EQ(s.bodies.back().name, "body1");
    EXPECT_EQ(s.bodies.back().accel, 0.1);
    EXPECT_TRUE(s.bodies.back().controlled);
}

}  // namespace

// ---- input files ----------------------------------------------------------------------------

// Only a regular file within its limit is read: a FIFO does not block (it is not opened), a
// directory or a device is not read as an empty or endless file.
// [[measure]]: instruments a scene shows from the start, each checked at the scene's K.
TEST(SceneFile, MeasureTablesDeclareInstrumentsAndRefuseWhatCannotBeMeasured) {
    Scene s;
    SceneError err;
    ASSERT_TRUE(parse_scene("curvature = -1\n[[measure]]\ninstrument = \"polygon\"\nsides = 3\naround = 7\nside = 1.2\n"
                            "[[measure]]\ninstrument = \"circle\"\npoints = [[1.2, 180]]\nradius = 0.8\n",
                            "m.toml", s, err))
        << err.to_string();
    ASSERT_EQ(s.measures.size(), 2u);
    EXPECT_EQ(s.measures[0].kind, noneuclid::geo::Instrument::polygon);
    EXPECT_EQ(s.measures[0].around, 7);
    EXPECT_EQ(s.measures[1].marks.size(), 1u);
    EXPECT_EQ(s.measures[1].radius, 0.8);
    struct Bad {
        const char* text;
        const char* message;
    };
    const Bad cases[] = {
        {"[[measure]]\ninstrument = \"hexagon\"\n", "m.toml:1:1: measure 1: expected instrument = \"triangle\", \"circle\", \"parallels\" or \"polygon\", found \"hexagon\""},
        {"[[measure]]\npoints = [[1, 0], [1, 90], [1, 180]]\n", "measure 1: expected instrument = "},
        {"[[measure]]\ninstrument = \"triangle\"\npoints = [[0.5, 0], [1, 0], [1.5, 0]]\n", "measure 1: triangle: the three marks lie on one geodesic: move one off it"},
        {"[[measure]]\ninstrument = \"triangle\"\npoints = [[1, 0], [1, 90]]\n", "measure 1: expected points = [[r, theta], ...] with 3 points for a triangle"},
        {"[[measure]]\ninstrument = \"triangle\"\npoints = [[1, 0], [9, 90], [1, 180]]\n", "measure 1: 'points' must be from 0 to 3.14159"},
        {"[[measure]]\ninstrument = \"polygon\"\nside = 0.1\n", "measure 1: polygon: those polygons close at no curvature from -1 to +1: change the side"},
        {"[[measure]]\ninstrument = \"polygon\"\nsides = 20\n", "measure 1: 'sides' must be from 3 to 12"},
        {"curvature = 1\n[[measure]]\ninstrument = \"circle\"\nradius = 3.5\n", "measure 1: circle: a length must be positive (and, on the sphere, shorter than halfway round)"},
        {"[[measure]]\ninstrument = \"circle\"\nwidth = 3\n", "measure 1: unknown key 'width'"},
    };
    for (const Bad& c : cases) {
        EXPECT_FALSE(parse_scene(c.text, "m.toml", s, err)) << c.text;
        EXPECT_NE(err.to_string().find(c.message), std::string::npos) << err.to_string();
    }
}

TEST(InputFiles, OnlyRegularFilesWithinTheLimit) {
    const std::string dir = ::testing::TempDir() + "input_files";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string fifo = dir + "/fifo", big = dir + "/big.toml", small = dir + "/small.toml";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    { std::ofstream(big) << std::string(kSceneFileLimit + 1, '#'); }
    { std::ofstream(small) << "curvature = 0.5\n"; }
    std::string text, why;
    EXPECT_FALSE(read_text_file(fifo, kSceneFileLimit, "a scene file", text, why));
    EXPECT_NE(why.find("not a regular file"), std::string::npos) << why;
    EXPECT_FALSE(read_text_file(dir, kSceneFileLimit, "a scene file", text, why));
    EXPECT_EQ(why, "it is a directory, not a file");
    EXPECT_FALSE(read_text_file("/dev/zero", kSceneFileLimit, "a scene file", text, why));
    EXPECT_NE(why.find("not a regular file"), std::string::npos) << why;
    EXPECT_FALSE(read_text_file(big, kSceneFileLimit, "a scene file", text, why));
    EXPECT_EQ(why, "it is 1048577 bytes, over the 1 MiB a scene file may have");
    EXPECT_FALSE(read_text_file(dir + "/none", kSceneFileLimit, "a scene file", text, why));
    EXPECT_NE(why.find("cannot read it (No such file or directory)"), std::string::npos) << why;
    ASSERT_TRUE(read_text_file(small, kSceneFileLimit, "a scene file", text, why)) << why;
    EXPECT_EQ(text, "curvature = 0.5\n");
    // Through the scene loader: one sentence with the path.
    Scene s;
    SceneError err;
    EXPECT_FALSE(load_scene_file(fifo, s, err));
    EXPECT_EQ(err.to_string().rfind(fifo + ": the scene file: it is not a regular file", 0), 0u) << err.to_string();
}

// ---- a scene file over the world's budget -----------------------------------------------------

TEST(Budget, ASceneFileOverItNamesTheGridAndWhatToLower) {
    Scene s;
    SceneError err;
    // 2 (2 * 314 + 1) = 1,258 lines (spacing 0.01 over R = pi), each 2 * 3,142 + 1 = 6,285 vertices
    // (a vertex every 0.001 along pi each way).
    EXPECT_FALSE(parse_scene("[[grid]]\nkind = \"axes\"\nspacing = 0.01\nstep = 0.001\n", "big.toml", s, err));
    EXPECT_EQ(err.to_string(), "big.toml:1:1: grid: it would have 7,906,530 vertices, over the 524,288 a world may have: "
                               "use fewer bodies or vertices (a larger spacing or step, a shorter length, fewer lines)");
    // Points: few bodies, but each tessellated finely.
    std::string text = "[[body]]\nname = \"b\"\ntessellation = 256\nvertices = [";
    for (int i = 0; i < 5000; ++i) text += (i ? ", " : "") + std::string("[0.1, ") + std::to_string(i * 0.072) + "]";
    text += "]\n";
    ASSERT_TRUE(parse_scene(text, "fine.toml", s, err)) << err.to_string();
    std::string why;
    EXPECT_FALSE(within_budget(s, why));
    EXPECT_EQ(why, "it would have 1,280,001 points to draw a frame, over the 1,048,576 a world may have: use fewer "
                   "bodies or vertices, or a lower tessellation");
}
