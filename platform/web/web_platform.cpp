// The process functions of app/platform.hpp in a web page: the browser's clock, and what a page
// has not (CPU time, signals, files, a choice of displays), each said in one sentence.
#include <emscripten.h>

#include "app/platform.hpp"

namespace noneuclid::platform {

namespace {
const char* const kNoFiles = "a web page writes no files: the page offers the recording for download instead";
}

// performance.now(): milliseconds since the page loaded, monotonic (to 0.1 ms, or finer where
// the page is cross-origin isolated).
int64_t monotonic_ns() { return static_cast<int64_t>(emscripten_get_now() * 1e6); }

// A page cannot ask for its CPU time: --stats reports the wall time alone there.
CpuTime cpu_time() { return {}; }
bool stderr_is_terminal() { return false; }
// The page passes the browser's language (or the address's ?lang=) as --lang.
std::string locale_name() { return {}; }

void prepare_process() {}

// A page gets no signals; it stops when the page says so (nw_stop) or is closed.
void catch_stop_signals() {}
int stop_signal() { return 0; }

DisplayChoice choose_display() { return {DisplayKind::png, "a web page has no X11 window and no framebuffer"}; }

bool AtomicFile::open(const std::string& path, std::string& error) {
    error = "cannot write " + path + ": " + kNoFiles + ".";
    return false;
}

bool AtomicFile::commit(std::string& error) {
    error = std::string(kNoFiles) + ".";
    return false;
}

void AtomicFile::abort() {}

const char* file_kind_name(FileKind) { return "a file of the page's memory"; }

bool output_allowed(const std::string& path, std::string& error) {
    error = "cannot write " + path + ": " + kNoFiles + ".";
    return false;
}

bool read_kept_file(const std::string&, std::size_t, std::string& out, FileKind& kind, std::string& error) {
    out.clear(), kind = FileKind::missing;
    error = "a web page keeps no files between runs";
    return false;
}

bool set_aside(const std::string&, const std::string&, std::string& aside, std::string& error) {
    aside.clear();
    error = "a web page keeps no files between runs";
    return false;
}

// A page is one process: there is nobody to take turns with.
DirectoryLock::DirectoryLock(const std::string&) {}
DirectoryLock::~DirectoryLock() = default;

std::string state_file(const std::string&, std::string& error) {
    error = "a web page keeps no files between runs";
    return {};
}

}  // namespace noneuclid::platform
