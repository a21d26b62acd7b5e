#include "app/run.hpp"

#include "app/setup.hpp"

namespace noneuclid::app {

void prepare_run(LiveRun& run, const Options& o) {
    run.scene = load_scene(o);
    run.font = load_font(o);
}

void compose_run(LiveRun& run, Options& o, const Script& script, Display& display, const char* display_name,
                 std::FILE* recording, HighScoreTable* scores) {
    if (o.legend.empty()) o.legend = display.legend();
    run.recorder = std::make_unique<Recorder>(recording);
    Recorder* recorder = recording ? run.recorder.get() : nullptr;
    const kinds::KindChoice kind = world_kind(o, run.scene);
    o.engine = kind.engine;  // (recorded: the replay runs on the engine this run did)
    if (recorder) record_settings(*recorder, o, display_name, run.font, display.canvas().format());
    run.session = make_session(kind, run.scene, session_options(o, run.scene, o.legend, kind), run.font.font, recorder, scores);
    LoopOptions lo;
    lo.frames = o.frames, lo.fps = o.fps, lo.stats = o.stats, lo.screenshot = o.screenshot;
    run.loop = std::make_unique<FrameLoop>(display, *run.session, o.actions.empty() ? nullptr : &script, recorder, lo);
}

}  // namespace noneuclid::app
