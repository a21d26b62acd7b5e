// `noneuclid dump` (a scene's state as JSON Lines, one line a frame) and `noneuclid render`
// (its last frame as a PNG, the run as an animated GIF).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "app/commands.hpp"
#include "app/gif_delays.hpp"
#include "app/picture.hpp"
#include "app/setup.hpp"

namespace noneuclid::app {

namespace {
bool put(const std::string& line) {
    return std::fwrite(line.data(), 1, line.size(), stdout) == line.size();
}
int write_failed() {
    std::fprintf(stderr, "noneuclid: cannot write the dump to standard output (%s): check where it goes.\n",
                 std::strerror(errno));
    return 1;
}
}  // namespace

int dump_command(int argc, char** argv, int first) {
    Script script;
    const Options o = layered_options(argc, argv, first, Command::dump, script);
    const world::Scene scene = load_scene(o);
    Options plain = o;
    plain.attract = 0, plain.threads = 1, plain.hud = false;
    const kinds::KindChoice kind = world_kind(o, scene);
    const std::unique_ptr<Session> s =
        make_session(kind, scene, session_options(plain, scene, o.legend, kind), render::builtin_font(), nullptr);
    ScriptPlayer player(script.events);
    std::string line;
    s->start(player);
    s->dump(o.width, o.height, line);
    if (!put(line)) return write_failed();
    for (long f = 0; f < o.frames; ++f) {
        s->advance(player);
        line.clear();
        s->dump(o.width, o.height, line);
        if (!put(line)) return write_failed();
    }
    return std::fflush(stdout) == 0 ? 0 : write_failed();
}

namespace {
// render --gif: the run's frames into an animated GIF, each shown for as long as the world time
// it stands for (app/gif_delays.hpp).
class GifFrames final : public FrameSink {
public:
    GifFrames(std::unique_ptr<platform::GifWriter> gif, double seconds) : gif_(std::move(gif)), delays_(seconds) {}
    bool frame(const render::Canvas& c, long) override { return gif_->frame(c, delays_.next(), error_); }
    bool finish(std::string& error) { return gif_->finish(error); }
    const std::string& error() const { return error_; }

private:
    std::unique_ptr<platform::GifWriter> gif_;
    GifDelays delays_;
    std::string error_;
};
}  // namespace

namespace {
// render's progress on a terminal, for a run long enough to wait for: "frame 1200 of 6000 (20%)",
// rewritten in place at each whole percent, and cleared at the end.
class TerminalProgress final : public Progress {
public:
    explicit TerminalProgress(bool on) : on_(on) {}
    ~TerminalProgress() {
        if (shown_) std::fprintf(stderr, "\r%*s\r", width_, "");
    }
    void at(long frame, long frames) override {
        if (!on_ || frames <= 0) return;
        const int percent = static_cast<int>(frame * 100 / frames);
        if (percent == percent_) return;
        percent_ = percent, shown_ = true;
        width_ = std::fprintf(stderr, "\rnoneuclid: frame %ld of %ld (%d%%)", frame, frames, percent);
    }

private:
    bool on_, shown_ = false;
    int percent_ = -1, width_ = 0;
};
// Long enough to show progress for: a GIF, or over ten seconds of world time.
bool long_run(const Options& o) { return !o.gif.empty() || o.frames > 600; }
}  // namespace

int render_command(int argc, char** argv, int first) {
    Script script;
    const Options o = layered_options(argc, argv, first, Command::render, script);
    if (o.out.empty() && o.gif.empty())
        usage_error("render needs --out FILE.png or --gif FILE.gif: where to write the picture.");
    check_outputs(o);
    if (!o.gif.empty() && o.dt * static_cast<double>(o.gif_every) > kGifMaxFrameSeconds) {
        char seconds[64];
        std::snprintf(seconds, sizeof seconds, "%g", o.dt * static_cast<double>(o.gif_every));
        usage_error("--gif-every " + std::to_string(o.gif_every) + ": each GIF frame would stand for " + seconds +
                    " s of world time, over the 655.35 s a GIF frame can be shown: use a smaller --gif-every or --dt.");
    }
    const world::Scene scene = load_scene(o);
    const platform::LoadedFont font = load_font(o);
    std::string error;
    std::unique_ptr<GifFrames> gif;
    if (!o.gif.empty()) {  // opened first: a bad path is said before the run
        std::unique_ptr<platform::GifWriter> w = platform::open_gif(o.gif, o.width, o.height, error);
        if (!w) {
            std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
            return 1;
        }
        gif = std::make_unique<GifFrames>(std::move(w), o.dt * static_cast<double>(o.gif_every));
    }
    platform::catch_stop_signals();  // a signal leaves --out and --gif as they were (render_picture, write_png, GifWriter)
    Picture picture;
    PictureResult r;
    {
        TerminalProgress progress(long_run(o) && platform::stderr_is_terminal());
        r = render_picture(o, scene, &script, font.font, picture, gif.get(), o.gif_every, &progress);
    }
    const std::string what = o.out.empty() ? o.gif : o.gif.empty() ? o.out : o.out + " and " + o.gif;
    if (r.stopped) {
        std::fprintf(stderr, "noneuclid: stopped by signal %d after %ld frames; %s is left as it was.\n",
                     platform::stop_signal(), r.frame, what.c_str());
        return 1;
    }
    if (r.refused || (gif && !gif->finish(error))) {
        std::fprintf(stderr, "noneuclid: %s\n", (r.refused ? gif->error() : error).c_str());
        return 1;
    }
    if (!o.out.empty() && !platform::write_png(o.out, picture.canvas, error)) {
        std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
        return 1;
    }
    std::fprintf(stderr, "noneuclid: wrote %s (%dx%d, %s, K = %.3f, frame %ld)\n", what.c_str(), o.width, o.height,
                 o.format.name, r.K, r.frame);
    return 0;
}

}  // namespace noneuclid::app
