// input_alloc_probe: proves that InputSource::read() allocates nothing, on a real kernel
// (tests/system/input.sh runs it in the VM while it toggles gpio-sim lines or injects keys).
// Linked statically with malloc, calloc, realloc and free wrapped (-Wl,--wrap=...), so every
// allocation counts, libgpiod's and libstdc++'s included.
//
//   input_alloc_probe gpio CHIP_LABEL SECONDS   lines 0-3 of the chip as buttons, 5 ms debounce
//   input_alloc_probe evdev SECONDS             every key device with KEY_UP or KEY_LEFT
//
// Prints "ready" once open, then after SECONDS "events N allocations M" (M counts only inside
// read()); exit 0 if M is 0, 1 otherwise, 2 on bad arguments or a failed open.
#include <poll.h>
#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "linux/input.hpp"

extern "C" {
void* __real_malloc(size_t);
void* __real_calloc(size_t, size_t);
void* __real_realloc(void*, size_t);
void __real_free(void*);

static long g_allocs = 0;
static bool g_counting = false;

void* __wrap_malloc(size_t n) {
    if (g_counting) ++g_allocs;
    return __real_malloc(n);
}
void* __wrap_calloc(size_t n, size_t s) {
    if (g_counting) ++g_allocs;
    return __real_calloc(n, s);
}
void* __wrap_realloc(void* p, size_t n) {
    if (g_counting) ++g_allocs;
    return __real_realloc(p, n);
}
void __wrap_free(void* p) {
    if (g_counting && p) ++g_allocs;
    __real_free(p);
}
}

namespace {

int64_t now_ns() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

}  // namespace

int main(int argc, char** argv) {
    namespace p = noneuclid::platform;
    using noneuclid::world::Action;
    // The counter must see both C (libgpiod) and C++ (operator new in libstdc++.a) allocations.
    g_counting = true;
    void* volatile c_block = std::malloc(16);
    int* volatile cxx_block = new int(1);
    g_counting = false;
    std::free(c_block);
    delete cxx_block;
    if (g_allocs < 2) {
        std::fprintf(stderr, "input_alloc_probe: the allocation counter saw %ld of 2 allocations (link with -Wl,--wrap=malloc...)\n", g_allocs);
        return 2;
    }
    g_allocs = 0;

    std::unique_ptr<p::InputSource> src;
    std::string error;
    double seconds = 0;
    if (argc == 4 && std::strcmp(argv[1], "gpio") == 0) {
        p::GpioConfig c;
        c.chips = {argv[2]};
        c.buttons = {{Action::thrust, 0, 0}, {Action::left, 1, 0}, {Action::right, 2, 0}, {Action::curvature_up, 3, 0}};
        c.debounce_ms = 5;
        src = p::open_gpio(c, error);
        seconds = std::atof(argv[3]);
    } else if (argc == 3 && std::strcmp(argv[1], "evdev") == 0) {
        p::EvdevConfig c;
        c.keys = {{Action::thrust, 103}, {Action::left, 105}};
        src = p::open_evdev(c, error);
        seconds = std::atof(argv[2]);
    } else {
        std::fprintf(stderr, "usage: input_alloc_probe gpio CHIP_LABEL SECONDS | evdev SECONDS\n");
        return 2;
    }
    if (!src) {
        std::fprintf(stderr, "input_alloc_probe: %s\n", error.c_str());
        return 2;
    }
    std::printf("ready\n");
    std::fflush(stdout);

    pollfd fds[16];
    noneuclid::world::InputEvent ev[32];
    long events = 0;
    const int64_t end = now_ns() + static_cast<int64_t>(seconds * 1e9);
    for (int64_t t = now_ns(); t < end; t = now_ns()) {
        int64_t wake = end;
        const int64_t d = src->deadline_ns();
        if (d >= 0 && d < wake) wake = d;
        const int n = src->fds(fds, 16);
        poll(fds, static_cast<nfds_t>(n), static_cast<int>(wake > t ? (wake - t + 999999) / 1000000 : 0));
        g_counting = true;
        events += src->read(ev, 32, now_ns());
        g_counting = false;
    }
    std::printf("events %ld allocations %ld\n", events, g_allocs);
    return g_allocs == 0 ? 0 : 1;
}
