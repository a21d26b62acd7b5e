// The native side of the web page's cost (tests/web/bench.mjs): the one frame loop, as `run`
// has it (HUD on, the keys' legend, the fixed engine unless told), on the headless display,
// 800x480 XRGB8888, timed as the page times itself: `reps` runs of `frames` frames back to
// back, the fastest kept (on a shared machine others' load only ever adds time).
//     build/release/bench_loop SCENE [FRAMES [REPS [ENGINE]]]
// prints one line: {"scene": ..., "frames": N, "ms": milliseconds a frame}
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/args.hpp"
#include "app/frame_loop.hpp"
#include "app/memory_display.hpp"
#include "app/setup.hpp"

int main(int argc, char** argv) {
    using namespace noneuclid;
    if (argc < 2 || argc > 5) {
        std::fprintf(stderr, "usage: bench_loop SCENE [FRAMES [REPS [ENGINE]]]\n");
        return 2;
    }
    try {
        app::Options o = app::defaults(app::Command::run);
        o.scene = argv[1];
        const long frames = argc > 2 ? app::Args::parse_count("FRAMES", argv[2], 1, 1000000) : 600;
        const long reps = argc > 3 ? app::Args::parse_count("REPS", argv[3], 1, 100) : 3;
        if (argc > 4) o.engine = app::engine_value("ENGINE", argv[4]);
        const world::Scene scene = app::load_scene(o);
        const platform::LoadedFont font = app::load_font(o);
        app::MemoryDisplay display(o.width, o.height, o.format);
        const auto session = app::make_session(app::world_kind(o, scene), scene, app::session_options(o, scene, "keys", app::world_kind(o, scene)), font.font, nullptr);
        app::LoopOptions lo;
        app::FrameLoop loop(display, *session, nullptr, nullptr, lo);
        double best = 1e300;
        for (long r = 0; r < reps; ++r) {
            const int64_t t0 = platform::monotonic_ns();
            for (long f = 0; f < frames; ++f) loop.tick();
            const double ms = static_cast<double>(platform::monotonic_ns() - t0) * 1e-6 / static_cast<double>(frames);
            if (ms < best) best = ms;
        }
        std::printf("{\"scene\": \"%s\", \"frames\": %ld, \"ms\": %.5f}\n", o.scene.c_str(), frames, best);
    } catch (const app::UsageError& e) {
        std::fprintf(stderr, "bench_loop: %s\n", e.message.c_str());
        return 2;
    }
    return 0;
}
