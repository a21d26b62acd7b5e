// The fbdev frame loop. See kiosk.hpp.
#include "linux/kiosk.hpp"

#include <poll.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iterator>

#include "linux/fbdev.hpp"
#include "run_stats.hpp"
#include "render/session.hpp"
#include "world/world.hpp"

namespace noneuclid::platform {
namespace {

template <class W>
int loop(Fbdev& fb, const world::Scene& scene, const KioskOptions& o, std::vector<std::unique_ptr<InputSource>>& inputs,
         render::ActionRecorder* recorder) {
    render::SessionOptions so;
    so.draw.projection = o.projection;
    so.draw.antialias = o.antialias;
    so.hud = o.hud;
    so.scene_name = scene.name.c_str();
    so.attract = o.attract;
    render::WorkerPool pool(o.threads);
    render::Session<W> session(scene, so, render::builtin_font(), recorder, &pool);

    constexpr int kMaxFds = 32;
    pollfd fds[kMaxFds];
    world::InputEvent events[64];
    const int64_t period = static_cast<int64_t>(1e9 / o.fps + 0.5);
    const int64_t start = monotonic_ns();
    int64_t next = start, fps_since = start;
    long frames = 0, fps_frames = 0;

    while (!ConsoleGuard::stop_requested && !session.quit && (o.frames == 0 || frames < o.frames)) {
        const bool vsync_paced = fb.vsync() && o.fps >= 55;  // present() waits for the refresh
        // Wait for the frame's deadline, handling input as it comes. Always read once, so the
        // first frame sees the buttons' initial levels.
        for (bool first = true;; first = false) {
            int n = 0;
            for (auto& in : inputs) n += in->fds(fds + n, kMaxFds - n);
            const int64_t t = monotonic_ns();
            int64_t wake = vsync_paced ? t : next;
            for (auto& in : inputs)
                if (const int64_t d = in->deadline_ns(); d >= 0 && d < wake) wake = d;
            const int timeout_ms = wake <= t ? 0 : static_cast<int>((wake - t + 999999) / 1000000);
            if (!first || n > 0) {
                if (poll(fds, static_cast<nfds_t>(n), first ? 0 : timeout_ms) < 0 && errno != EINTR) {
                    std::fprintf(stderr, "noneuclid: waiting for the buttons failed (%s): check the input devices and restart.\n",
                                 std::strerror(errno));
                    return 1;
                }
            }
            if (ConsoleGuard::stop_requested) break;
            const int64_t after = monotonic_ns();
            for (auto& in : inputs) {
                const int got = in->read(events, static_cast<int>(std::size(events)), after);
                for (int i = 0; i < got; ++i) session.control(events[i]);
            }
            if (session.quit || vsync_paced || after >= next) break;
        }
        if (ConsoleGuard::stop_requested || session.quit) break;
        session.frame(fb.back());
        fb.present();
        ++frames, ++fps_frames;
        const int64_t t = monotonic_ns();
        if (t - fps_since >= 500000000) {
            session.fps = static_cast<double>(fps_frames) * 1e9 / static_cast<double>(t - fps_since);
            fps_since = t, fps_frames = 0;
        }
        next += period;
        if (t - next > period) next = t;  // after a stall, start again from now
    }
    if (ConsoleGuard::stop_requested)
        std::fprintf(stderr, "noneuclid: stopped by signal %d after %ld frames.\n", ConsoleGuard::stop_signal(), frames);
    if (o.stats) print_run_stats(frames, static_cast<double>(monotonic_ns() - start) * 1e-9);
    return 0;
}

}  // namespace

int run_fbdev(const world::Scene& scene, const KioskOptions& o, std::vector<std::unique_ptr<InputSource>>& inputs) {
    Fbdev fb;
    std::string error;
    if (!fb.open(o.device, error)) {
        std::fprintf(stderr, "noneuclid: %s.\n", error.c_str());
        return 2;
    }
    std::fprintf(stderr, "noneuclid: framebuffer %s\n", fb.describe().c_str());
    std::FILE* rec = nullptr;
    if (!o.record.empty()) {
        rec = std::fopen(o.record.c_str(), "w");
        if (!rec) {
            std::fprintf(stderr, "noneuclid: cannot write the recording %s (%s): check the directory.\n", o.record.c_str(),
                         std::strerror(errno));
            return 2;
        }
        std::fprintf(rec, "# noneuclid run: scene %s, engine %s, world time 1/60 s per frame; replay with\n"
                          "# noneuclid render --scene %s --engine %s --actions THIS_FILE --frames N\n",
                     scene.name.c_str(), o.engine.c_str(), scene.name.c_str(), o.engine.c_str());
    }
    render::FileRecorder recorder(rec);
    int status = 0;
    {
        ConsoleGuard console;
        std::fprintf(stderr, "noneuclid: %s\n", console.note.c_str());
        render::ActionRecorder* r = rec ? &recorder : nullptr;
        if (o.engine == "double") status = loop<world::World<double>>(fb, scene, o, inputs, r);
        else if (o.engine == "float") status = loop<world::World<float>>(fb, scene, o, inputs, r);
        else if (o.engine == "paper") status = loop<world::World<double, true>>(fb, scene, o, inputs, r);
        else status = loop<world::World<fx::fixed>>(fb, scene, o, inputs, r);
    }
    if (rec && std::fclose(rec) != 0) {
        std::fprintf(stderr, "noneuclid: could not finish writing the recording %s: check the disk.\n", o.record.c_str());
        status = status ? status : 1;
    }
    return status;
}

}  // namespace noneuclid::platform
