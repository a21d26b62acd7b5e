#include "app/frame_loop.hpp"

#include <cstdio>

#include "app/platform.hpp"

namespace noneuclid::app {

FrameLoop::FrameLoop(Display& display, Session& session, const Script* script, Recorder* recorder,
                     const LoopOptions& o)
    : display_(display), session_(session), recorder_(recorder), o_(o) {
    if (script) player_ = ScriptPlayer(script->events);
    session_.start(player_);
    platform::catch_stop_signals();
    period_ = static_cast<int64_t>(1e9 / (o_.fps > 0 ? o_.fps : 60) + 0.5);
    start_ = next_ = fps_since_ = platform::monotonic_ns();
}

bool FrameLoop::tick() {
    if (failed_ || (o_.frames > 0 && frames_ >= o_.frames)) return false;
    // Input until the frame is due: now, for a display that paces itself or that nobody watches.
    const bool sleep = display_.realtime() && !display_.paced_by_refresh();
    if (!display_.wait(sleep ? next_ : 0, *this)) {
        failed_ = true;
        return false;
    }
    if (display_.closing() || session_.quit() || platform::stop_signal()) return false;
    const render::Canvas canvas = display_.canvas();
    if (recorder_ && (canvas.width() != width_ || canvas.height() != height_)) {
        width_ = canvas.width(), height_ = canvas.height();
        recorder_->setting("size", std::to_string(width_) + "x" + std::to_string(height_));
    }
    session_.advance(player_);
    if (sound_) sound_->frame(session_.sound(), session_.options().dt);
    session_.draw(canvas);
    display_.present();
    ++frames_, ++fps_frames_;
    const int64_t t = platform::monotonic_ns();
    if (t - fps_since_ >= 500000000) {
        session_.set_fps(static_cast<double>(fps_frames_) * 1e9 / static_cast<double>(t - fps_since_));
        fps_since_ = t, fps_frames_ = 0;
    }
    next_ += period_;
    if (t - next_ > period_) next_ = t;  // after a stall, start again from now
    return true;
}

int write_screenshot(Display& display, const std::string& path, const std::string& where) {
    Picture shot;
    std::string error;
    if (!display.read_back(shot, error) || !platform::write_png(path, shot.canvas, error)) {
        std::fprintf(stderr, "noneuclid: the screenshot: %s\n", error.c_str());
        return 1;
    }
    std::fprintf(stderr, "noneuclid: wrote %s (%dx%d, %s)\n", path.c_str(), shot.canvas.width(), shot.canvas.height(),
                 where.c_str());
    return 0;
}

int FrameLoop::finish() {
    int status = failed_ ? 1 : 0;
    if (const int sig = platform::stop_signal())
        std::fprintf(stderr, "noneuclid: stopped by signal %d after %ld frames.\n", sig, frames_);
    if (recorder_) recorder_->setting("frames", std::to_string(frames_));
    if (!o_.screenshot.empty()) {
        char where[64];
        std::snprintf(where, sizeof where, "frame %ld, K = %.3f", session_.frame(), session_.curvature());
        if (write_screenshot(display_, o_.screenshot, where) != 0) status = status ? status : 1;
    }
    if (o_.stats) {
        const double wall = static_cast<double>(platform::monotonic_ns() - start_) * 1e-9;
        const platform::CpuTime cpu = platform::cpu_time();
        const std::string note = display_.stats_note();
        std::fprintf(stderr,
                     "noneuclid: %ld frames in %.2f s (%.1f fps), CPU %.2f s user + %.2f s system = %.1f%% of one core%s%s\n",
                     frames_, wall, wall > 0 ? static_cast<double>(frames_) / wall : 0.0, cpu.user, cpu.system,
                     wall > 0 ? 100 * (cpu.user + cpu.system) / wall : 0.0, note.empty() ? "" : ", ", note.c_str());
    }
    return status;
}

}  // namespace noneuclid::app
