// `--stats` at exit, for every display's run loop: frames, wall time and the CPU this process
// used, in one line on stderr (POSIX getrusage).
#pragma once

#include <sys/resource.h>

#include <cstdio>

namespace noneuclid::platform {

// "noneuclid: N frames in W s (F fps), CPU U s user + S s system = P% of one core[, extra]"
inline void print_run_stats(long frames, double wall_seconds, const char* extra = nullptr) {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    const double user = static_cast<double>(u.ru_utime.tv_sec) + static_cast<double>(u.ru_utime.tv_usec) * 1e-6;
    const double sys = static_cast<double>(u.ru_stime.tv_sec) + static_cast<double>(u.ru_stime.tv_usec) * 1e-6;
    const double wall = wall_seconds;
    std::fprintf(stderr, "noneuclid: %ld frames in %.2f s (%.1f fps), CPU %.2f s user + %.2f s system = %.1f%% of one core%s%s\n",
                 frames, wall, wall > 0 ? static_cast<double>(frames) / wall : 0.0, user, sys,
                 wall > 0 ? 100 * (user + sys) / wall : 0.0, extra ? ", " : "", extra ? extra : "");
}

}  // namespace noneuclid::platform
