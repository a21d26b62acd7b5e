// The clock, the process's CPU time, whether stderr is a terminal and the locale's name
// (app/platform.hpp), from POSIX.
#include <cstdlib>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "app/platform.hpp"

namespace noneuclid::platform {

int64_t monotonic_ns() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

CpuTime cpu_time() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    auto seconds = [](timeval t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
    return {seconds(u.ru_utime), seconds(u.ru_stime)};
}

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

std::string locale_name() {
    for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
        const char* v = std::getenv(name);
        if (v && *v) return v;
    }
    return {};
}

}  // namespace noneuclid::platform
