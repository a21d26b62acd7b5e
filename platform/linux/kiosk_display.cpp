// The kiosk as a display (app/display.hpp): the framebuffer (fbdev.hpp), the console it owns
// for the program's life, and the board's buttons: GPIO lines and evdev keys (InputSet), polled
// with the frame's deadline as the timeout, so the loop sleeps until a button or the frame is due.
#include <cstdio>
#include <iterator>

#include "app/platform.hpp"
#include "linux/fbdev.hpp"
#include "linux/input.hpp"
#include "linux/input_set.hpp"

namespace noneuclid::platform {
namespace {

class KioskDisplay final : public app::Display {
public:
    bool open(const KioskSpec& spec, std::string& error) {
        if (!fb_.open(spec.device, error)) {
            error += ".";
            return false;
        }
        std::fprintf(stderr, "noneuclid: framebuffer %s\n", fb_.describe().c_str());
        if (!open_board_inputs(spec.board, spec.input, sources_, error)) return false;
        if (sources_.empty()) std::fprintf(stderr, "noneuclid: no buttons: the world runs on its own.\n");
        std::vector<InputSource*> sources;
        for (const auto& in : sources_) sources.push_back(in.get());
        inputs_ = InputSet(std::move(sources));
        console_ = std::make_unique<ConsoleGuard>();
        std::fprintf(stderr, "noneuclid: %s\n", console_->note.c_str());
        vsync_pace_ = spec.fps >= 55;
        return true;
    }

    render::Canvas canvas() override { return fb_.back(); }
    void present() override { fb_.present(); }
    bool wait(int64_t deadline_ns, app::InputSink& sink) override {
        // Always read once, so that the first frame sees the buttons' levels at start.
        for (;;) {
            const int got = inputs_.read(events_, static_cast<int>(std::size(events_)), monotonic_ns());
            for (int i = 0; i < got; ++i) sink.input(events_[i]);
            if (stop_signal() || monotonic_ns() >= deadline_ns) return true;
            std::string error;
            // A device in error is the kiosk's to outlive (read() drops an unplugged one): only a
            // failing poll() ends the run.
            if (inputs_.wait(deadline_ns, error) == InputSet::Woke::failed) {
                std::fprintf(stderr, "noneuclid: %s: check the input devices and restart.\n", error.c_str());
                return false;
            }
        }
    }
    bool closing() const override { return false; }
    bool paced_by_refresh() const override { return vsync_pace_ && fb_.vsync(); }
    bool read_back(app::Picture& out, std::string&) override {
        out.canvas = fb_.read_back(out.pixels);
        return true;
    }
    const char* legend() const override { return "buttons"; }

private:
    Fbdev fb_;
    std::vector<std::unique_ptr<InputSource>> sources_;
    InputSet inputs_{{}};
    std::unique_ptr<ConsoleGuard> console_;  // made last: restored first
    bool vsync_pace_ = false;
    world::InputEvent events_[64];
};

}  // namespace

std::unique_ptr<app::Display> open_kiosk(const KioskSpec& spec, std::string& error) {
    auto d = std::make_unique<KioskDisplay>();
    if (!d->open(spec, error)) return nullptr;
    return d;
}

}  // namespace noneuclid::platform
