// One live run, set up the same way wherever it runs (`noneuclid run` on a window, the kiosk or
// the headless display; the web page): its scene and font loaded (prepare_run, before any
// display opens, so that a bad file is said first), then its recorder, session and frame loop
// on the caller's display (compose_run). The caller owns the display and the recording file,
// and runs the loop.
#pragma once

#include <cstdio>
#include <memory>

#include "app/display.hpp"
#include "app/frame_loop.hpp"
#include "app/high_scores.hpp"
#include "app/options.hpp"
#include "app/platform.hpp"
#include "app/recorder.hpp"
#include "app/script.hpp"
#include "app/session.hpp"
#include "world/scene.hpp"

namespace noneuclid::app {

struct LiveRun {
    world::Scene scene;
    platform::LoadedFont font;
    std::unique_ptr<Recorder> recorder;  // writes to the recording file, or records nothing
    std::unique_ptr<Session> session;
    std::unique_ptr<FrameLoop> loop;
};

// The scene and the HUD's font of o (a UsageError for a bad one).
void prepare_run(LiveRun& run, const Options& o);
// The rest on `display` (named `display_name` in the recording): o's legend, if unset, becomes
// the display's; `recording` (may be null) gets the settings, then every control; `scores` (may
// be null) is told of each game. `script` (o.actions' events) and everything passed must
// outlive the run.
void compose_run(LiveRun& run, Options& o, const Script& script, Display& display, const char* display_name,
                 std::FILE* recording, HighScoreTable* scores);

}  // namespace noneuclid::app
