// SIGINT, SIGTERM, SIGHUP and SIGQUIT as a request to stop (app/platform.hpp): the frame loop
// finishes the frame, writes the recording's end and the screenshot, and the displays restore
// what they changed (the console) on the way out; render and demo leave their files as they
// were. And SIGXFSZ and SIGPIPE ignored, so that a file-size limit is an error like a full disk
// and a closed pipe (`noneuclid dump | head`) a failed write the program reports, not a silent end.
#include <csignal>

#include "app/platform.hpp"

namespace noneuclid::platform {

namespace {
volatile std::sig_atomic_t g_stop_signal = 0;
void on_stop(int sig) { g_stop_signal = sig; }
}  // namespace

void prepare_process() {
    std::signal(SIGXFSZ, SIG_IGN);
    std::signal(SIGPIPE, SIG_IGN);
}

void catch_stop_signals() {
    struct sigaction stop{};
    stop.sa_handler = on_stop;  // no SA_RESTART: poll() and nanosleep return EINTR at once
    sigemptyset(&stop.sa_mask);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaction(s, &stop, nullptr);
}

int stop_signal() { return g_stop_signal; }

}  // namespace noneuclid::platform
