// The kiosk as a display (app/display.hpp): the framebuffer (fbdev.hpp), the console it owns
// for the program's life, and the board's buttons: GPIO lines and evdev keys, polled with the
// frame's deadline as the timeout, so the loop sleeps until a button or the frame is due.
#include <poll.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iterator>

#include "app/platform.hpp"
#include "linux/fbdev.hpp"
#include "linux/input.hpp"

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
        if (!open_board_inputs(spec.board, spec.input, inputs_, error)) return false;
        if (inputs_.empty()) std::fprintf(stderr, "noneuclid: no buttons: the world runs on its own.\n");
        console_ = std::make_unique<ConsoleGuard>();
        std::fprintf(stderr, "noneuclid: %s\n", console_->note.c_str());
        vsync_pace_ = spec.fps >= 55;
        return true;
    }

    render::Canvas canvas() override { return fb_.back(); }
    void present() override { fb_.present(); }
    bool wait(int64_t deadline_ns, app::InputSink& sink) override {
        // Always read once, so that the first frame sees the buttons' levels at start.
        for (bool first = true;; first = false) {
            int n = 0;
            for (auto& in : inputs_) n += in->fds(fds_ + n, kMaxFds - n);
            const int64_t t = monotonic_ns();
            int64_t wake = deadline_ns;
            for (auto& in : inputs_)
                if (const int64_t d = in->deadline_ns(); d >= 0 && d < wake) wake = d;
            const int timeout_ms = wake <= t ? 0 : static_cast<int>((wake - t + 999999) / 1000000);
            if (!first || n > 0) {
                if (poll(fds_, static_cast<nfds_t>(n), first ? 0 : timeout_ms) < 0 && errno != EINTR) {
                    std::fprintf(stderr,
                                 "noneuclid: waiting for the buttons failed (%s): check the input devices and restart.\n",
                                 std::strerror(errno));
                    return false;
                }
            }
            if (stop_signal()) return true;
            const int64_t after = monotonic_ns();
            for (auto& in : inputs_) {
                const int got = in->read(events_, static_cast<int>(std::size(events_)), after);
                for (int i = 0; i < got; ++i) sink.input(events_[i]);
            }
            if (after >= deadline_ns) return true;
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
    static constexpr int kMaxFds = 32;
    Fbdev fb_;
    std::vector<std::unique_ptr<InputSource>> inputs_;
    std::unique_ptr<ConsoleGuard> console_;  // made last: restored first
    bool vsync_pace_ = false;
    pollfd fds_[kMaxFds];
    world::InputEvent events_[64];
};

}  // namespace

std::unique_ptr<app::Display> open_kiosk(const KioskSpec& spec, std::string& error) {
    auto d = std::make_unique<KioskDisplay>();
    if (!d->open(spec, error)) return nullptr;
    return d;
}

}  // namespace noneuclid::platform
