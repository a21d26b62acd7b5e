// The fuzzing harnesses' bodies (tests/fuzz/README.md): each takes one input and calls the same
// entry points the program does. libFuzzer runs them (fuzz_main.cpp, the `fuzz` preset, clang);
// the normal suite replays every input under tests/fuzz/regressions/<name>/ through them
// (replay_test.cpp, gcc), so an input that once crashed is tried on every build.
//
// A harness aborts (a crash for libFuzzer, a failed test for the replay) when a parser breaks
// its contract: a sentence that is not one clean line with its place, or a result outside the
// documented ranges. Crashes and sanitizer reports abort by themselves.
#pragma once

#include <string_view>

namespace noneuclid::fuzz {

void scene(std::string_view input);    // files::parse_scene
void board(std::string_view input);    // files::parse_board
void actions(std::string_view input);  // app::parse_script
// A scene file, then a line "%%", then an actions file: both parsed, the scene built as
// World<fixed>, World<double>, World<float> and World<double, geo::Paper>, the actions applied while
// each steps some frames, and the last frame dumped (files::dump_frame).
void world(std::string_view input);
// The C interface (src/capi/noneuclid.h): a scene text, a line "%%", then operations, 4 bytes
// each, on the world made from it (on fixed or double, or a bad engine's name, by the input's
// length): steps, K, controls, views, drawings of any size, stride,
// format and buffer (the buffer exactly as large as said: a write past it is ASan's), bodies and
// events by any index. Every status must be the one the arguments call for, and every failure
// one plain line in nw_last_error.
void capi(std::string_view input);

struct Harness {
    const char* name;  // the directory under regressions/ and seeds/
    void (*run)(std::string_view);
};
inline constexpr Harness kHarnesses[] = {
    {"scene", scene}, {"board", board}, {"actions", actions}, {"world", world}, {"capi", capi}};

// The largest scene the harnesses build, in vertices (grid lines included) and in edge points
// (vertices times tessellation): in-range values can ask for millions (a [[grid]] with
// spacing = 0.01, step = 0.001, length = 10000), which says nothing about parsing and would
// make the fuzzer spend its time allocating. Bigger inputs are skipped, not built.
inline constexpr double kMaxVertices = 100000;
inline constexpr double kMaxEdgePoints = 20000;

}  // namespace noneuclid::fuzz
