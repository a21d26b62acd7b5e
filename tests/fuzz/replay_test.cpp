// Every input a fuzzer ever crashed on (tests/fuzz/regressions/<harness>/), and every seed, run
// through the same harness the fuzzer calls (harness.hpp), in the normal suite: a parser that
// crashes, hits undefined behaviour under the sanitizers or breaks a harness's checks on one of
// them fails here, on every build, without clang or libFuzzer.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness.hpp"

namespace {

namespace fs = std::filesystem;
using noneuclid::fuzz::Harness;

const Harness& harness(const std::string& name) {
    for (const Harness& h : noneuclid::fuzz::kHarnesses)
        if (name == h.name) return h;
    throw std::runtime_error("no harness " + name);
}

// Runs every regular file of `dir` through the harness; returns how many.
int replay(const Harness& h, const fs::path& dir) {
    if (!fs::is_directory(dir)) return 0;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.string());
        std::ifstream in(f, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        h.run(text.str());
    }
    return static_cast<int>(files.size());
}

const fs::path kFuzz = NONEUCLID_FUZZ_DIR;

// The crashes found so far, for each harness, and its seeds (which must exist: a harness that
// is never run here would be a test that cannot fail).
void replay_all(const char* name, int expected_regressions_at_least) {
    const Harness& h = harness(name);
    EXPECT_GE(replay(h, kFuzz / "regressions" / name), expected_regressions_at_least);
    EXPECT_GT(replay(h, kFuzz / "seeds" / name), 0);
}

TEST(FuzzRegressions, Scene) { replay_all("scene", 1); }
TEST(FuzzRegressions, Board) { replay_all("board", 1); }
TEST(FuzzRegressions, Actions) { replay_all("actions", 2); }
TEST(FuzzRegressions, World) { replay_all("world", 0); }
TEST(FuzzRegressions, CApi) { replay_all("capi", 0); }

// The scene and board harnesses on the project's own files: the examples, the boards.
TEST(FuzzRegressions, TheProjectsFilesAsSeeds) {
    const fs::path source = NONEUCLID_SOURCE_DIR;
    EXPECT_GT(replay(harness("scene"), source / "tests/files/data"), 0);
    EXPECT_GT(replay(harness("board"), source / "boards"), 0);
}

}  // namespace
