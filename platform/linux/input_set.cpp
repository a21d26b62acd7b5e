#include "linux/input_set.hpp"

#include <cerrno>
#include <climits>
#include <cstring>

namespace noneuclid::platform {

int InputSet::read(world::InputEvent* out, int max, int64_t now_ns) {
    int n = 0;
    for (InputSource* s : sources_) n += s->read(out + n, max - n, now_ns);
    return n;
}

InputSet::Woke InputSet::wait(int64_t until_ns, std::string& error) {
    int64_t wake = until_ns;
    int n = 0;
    for (InputSource* s : sources_) {
        n += s->fds(fds_ + n, kMaxFds - n);
        const int64_t d = s->deadline_ns();
        if (d >= 0 && (wake < 0 || d < wake)) wake = d;
    }
    int live = 0;
    for (int i = 0; i < n; ++i) live += fds_[i].fd >= 0;
    if (live == 0 && wake < 0) {
        error = "every input device has gone away (unplugged?): reconnect it and start again";
        return Woke::gone;
    }
    int timeout_ms = -1;
    if (wake >= 0) {
        const int64_t now = monotonic_ns();
        const int64_t ms = wake > now ? (wake - now + 999999) / 1000000 : 0;
        timeout_ms = ms > INT_MAX ? INT_MAX : static_cast<int>(ms);
    }
    if (poll(fds_, static_cast<nfds_t>(n), timeout_ms) < 0) {
        if (errno == EINTR) return Woke::ready;
        error = std::string("polling the input devices failed: ") + std::strerror(errno);
        return Woke::failed;
    }
    bool bad = false;
    for (int i = 0; i < n; ++i)
        bad |= fds_[i].fd >= 0 && (fds_[i].revents & (POLLERR | POLLNVAL)) && !(fds_[i].revents & POLLIN);
    if (!bad) {
        errors_in_a_row_ = 0;
        return Woke::ready;
    }
    if (errors_in_a_row_++ == 0) return Woke::ready;
    error = "an input device keeps reporting errors (unplugged, or its GPIO chip removed?): check the connection and "
            "start again";
    return Woke::errors;
}

}  // namespace noneuclid::platform
