// Kiosk input (platform/linux) on a synthetic clock and a pipe: the debounce state machine
// (presses at the first edge, bounces swallowed, short presses kept, buttons independent) and
// print_input_events (stops after its count, its timeout, at the end of the source).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "buttons.hpp"
#include "linux/gpio_common.hpp"
#include "linux/input.hpp"
#include "linux/input_set.hpp"
#include "linux/input_set.hpp"

namespace p = noneuclid::platform;
namespace gd = noneuclid::platform::gpio_detail;
using noneuclid::test::two_buttons;
using noneuclid::world::Action;
using noneuclid::world::InputEvent;

namespace {

// ---------------------------------------------------------------------------------------------
// The debounce state machine on a synthetic clock (ms -> ns)
// ---------------------------------------------------------------------------------------------

constexpr int64_t ms(int64_t v) { return v * 1000000; }

struct Tracker {
    explicit Tracker(unsigned debounce_ms) {
        auto c = two_buttons();
        c.debounce_ms = debounce_ms;
        t.init(c, ms(debounce_ms));
    }
    std::string drain() {
        InputEvent ev[8];
        std::string s;
        for (int n; (n = t.pop(ev, 8)) > 0;)
            for (int i = 0; i < n; ++i)
                s += std::string(ev[i].pressed ? "+" : "-") + noneuclid::world::action_name(ev[i].control) + " ";
        return s;
    }
    gd::ButtonTracker t;
    int level[2] = {0, 0};  // what expire() reads
    void expire(int64_t now) {
        t.expire(now, [this](int i) { return level[i]; });
    }
};

TEST(Debounce, InitialLevelGivesAPressForAHeldButton) {
    Tracker k(10);
    k.t.set_initial(0, false);
    k.t.set_initial(1, true);
    EXPECT_EQ(k.drain(), "+left ");
    k.t.edge(1, true, ms(5));  // already pressed: nothing new
    EXPECT_EQ(k.drain(), "");
}

TEST(Debounce, BouncingPressGivesOnePressAtTheFirstEdge) {
    Tracker k(10);
    k.t.set_initial(0, false);
    k.t.edge(0, true, ms(100));  // reported at once: no added latency
    EXPECT_EQ(k.drain(), "+thrust ");
    EXPECT_EQ(k.t.deadline(), ms(110));
    k.t.edge(0, false, ms(101));
    k.t.edge(0, true, ms(102));
    k.t.edge(0, false, ms(103));
    k.t.edge(0, true, ms(104));
    k.level[0] = 1;
    k.expire(ms(109));  // window still open
    EXPECT_EQ(k.drain(), "");
    k.expire(ms(110));  // closes; the level is still pressed
    EXPECT_EQ(k.drain(), "");
    EXPECT_EQ(k.t.deadline(), -1);
    k.t.edge(0, false, ms(300));
    EXPECT_EQ(k.drain(), "-thrust ");
}

TEST(Debounce, PressShorterThanTheWindowStillGivesItsRelease) {
    Tracker k(10);
    k.t.edge(0, true, ms(0));
    k.t.edge(0, false, ms(3));
    k.level[0] = 0;
    k.expire(ms(10));
    EXPECT_EQ(k.drain(), "+thrust -thrust ");
    // The release opened a new window.
    EXPECT_EQ(k.t.deadline(), ms(20));
}

TEST(Debounce, ButtonsAreIndependent) {
    Tracker k(10);
    k.t.edge(0, true, ms(0));
    k.t.edge(1, true, ms(1));  // another button inside thrust's window
    EXPECT_EQ(k.drain(), "+thrust +left ");
    EXPECT_EQ(k.t.deadline(), ms(10));
}

TEST(Debounce, ZeroDebounceReportsEveryChange) {
    Tracker k(0);
    k.t.edge(0, true, ms(0));
    k.t.edge(0, false, ms(0));
    k.t.edge(0, false, ms(0));  // a repeated level is not a change
    k.t.edge(0, true, ms(0));
    EXPECT_EQ(k.drain(), "+thrust -thrust +thrust ");
    EXPECT_EQ(k.t.deadline(), -1);
}

TEST(Debounce, PopHonoursMax) {
    Tracker k(0);
    k.t.edge(0, true, 0);
    k.t.edge(1, true, 0);
    k.t.edge(0, false, 0);
    InputEvent ev[2];
    EXPECT_EQ(k.t.pop(ev, 2), 2);
    EXPECT_EQ(ev[0].control, Action::thrust);
    EXPECT_TRUE(ev[0].pressed);
    EXPECT_EQ(ev[1].control, Action::left);
    EXPECT_EQ(k.drain(), "-thrust ");
}

// ---------------------------------------------------------------------------------------------
// print_input_events over a pipe: each byte written is one event ('T' press thrust, 't' release)
// ---------------------------------------------------------------------------------------------

class PipeSource final : public p::InputSource {
public:
    PipeSource() {
        if (pipe2(fd_, O_NONBLOCK | O_CLOEXEC) != 0) std::abort();
    }
    ~PipeSource() override {
        if (fd_[0] >= 0) close(fd_[0]);
        if (fd_[1] >= 0) close(fd_[1]);
    }
    std::string describe() const override { return "pipe"; }
    int fds(pollfd* out, int max) override {
        if (max < 1) return 0;
        out[0] = pollfd{fd_[0], POLLIN, 0};
        return 1;
    }
    int read(InputEvent* out, int max, int64_t) override {
        int n = 0;
        char c;
        while (n < max && ::read(fd_[0], &c, 1) == 1) {
            const bool pressed = c >= 'A' && c <= 'Z';
            out[n++] = {pressed ? Action::thrust : Action::left, pressed};
        }
        return n;
    }
    void send(const char* s) { ASSERT_EQ(::write(fd_[1], s, std::strlen(s)), static_cast<ssize_t>(std::strlen(s))); }
    int fd_[2] = {-1, -1};
};

std::string run_print(p::InputSource& src, long max, double timeout, int& rc) {
    std::FILE* f = std::tmpfile();
    p::InputSet set({&src});
    rc = p::print_input_events(set, max, timeout, f);
    std::rewind(f);
    std::string s;
    for (int c; (c = std::fgetc(f)) != EOF;) s += static_cast<char>(c);
    std::fclose(f);
    return s;
}

TEST(PrintEvents, StopsAfterMaxEvents) {
    PipeSource src;
    src.send("TtT");
    int rc = -1;
    EXPECT_EQ(run_print(src, 2, 5.0, rc), "press thrust\nrelease left\n");
    EXPECT_EQ(rc, 0);
}

TEST(PrintEvents, TimeoutEndsAQuietWait) {
    PipeSource src;
    src.send("T");
    int rc = -1;
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_EQ(run_print(src, 0, 0.2, rc), "press thrust\n");
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(rc, 0);
    EXPECT_GE(s, 0.2);
    EXPECT_LT(s, 5.0);
}

TEST(PrintEvents, BadFdIsAnErrorNotASpin) {
    PipeSource src;
    close(src.fd_[0]);
    src.fd_[0] = 1000;  // not open: poll() says POLLNVAL every time
    ASSERT_EQ(fcntl(src.fd_[0], F_GETFD), -1);
    int rc = -1;
    run_print(src, 0, 0, rc);  // no timeout and no limit: it must end by itself
    src.fd_[0] = -1;
    EXPECT_NE(rc, 0);
}

TEST(PrintEvents, BadArguments) {
    PipeSource src;
    int rc = -1;
    run_print(src, -1, 0, rc);
    EXPECT_NE(rc, 0);
    run_print(src, 0, -1, rc);
    EXPECT_NE(rc, 0);
}

}  // namespace
