// The board under emulation (board.hpp): qemu-system-arm -M mps2-an385 with semihosting. Its
// command line (qemu's `-semihosting-config arg=...` words) is
//     FIRMWARE RECORDING OUTDIR [EVERY]
// the recording (an actions file, app/script.hpp) is read from the host, and every EVERY-th
// frame (default 1), and the last, is written to the host as OUTDIR/frame-NNNNNN.rgb565: the
// canvas's bytes, 240 rows of 480, RGB565 little-endian. EVERY 0 writes none (the instruction
// counts). The last line says how the run went; the exit status is qemu's.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "board.hpp"
#include "semihosting.hpp"
#include "kinds/step.hpp"

namespace noneuclid::mcu::board {
namespace {

namespace sh = semihosting;

char g_cmdline[512];
char g_text[8192];  // the recording's text
const char* g_outdir = nullptr;
long g_every = 1, g_frames = 0;
kinds::DueEvents<RecordedEvent> g_due;  // the recording's events (kinds/step.hpp)

// The next word of the command line, NUL-terminated in place.
char* word(char** at) {
    char* p = *at;
    while (*p == ' ') ++p;
    if (*p == '\0') return nullptr;
    char* const w = p;
    while (*p != '\0' && *p != ' ') ++p;
    if (*p != '\0') *p++ = '\0';
    *at = p;
    return w;
}

bool fail(const char* sentence) {
    sh::print(sentence);
    sh::print("\n");
    return false;
}

}  // namespace

bool start(Recording& setup) {
    if (!sh::command_line(g_cmdline, sizeof g_cmdline)) return fail("noneuclid firmware: no command line (semihosting).");
    char* at = g_cmdline;
    word(&at);  // (the firmware's own name)
    const char* path = word(&at);
    g_outdir = word(&at);
    if (const char* every = word(&at)) g_every = std::strtol(every, nullptr, 10);
    if (!path || !g_outdir || g_every < 0)
        return fail("noneuclid firmware: usage: FIRMWARE RECORDING OUTDIR [EVERY] (qemu's -semihosting-config arg=...).");
    const int h = sh::open(path, "rb");
    if (h < 0) return fail("noneuclid firmware: cannot open the recording (check the path).");
    const long size = sh::length(h);
    if (size < 0 || static_cast<unsigned long>(size) >= sizeof g_text) {
        sh::close(h);
        return fail("noneuclid firmware: the recording is over 8 KB, or unreadable.");
    }
    const std::size_t got = sh::read(h, g_text, static_cast<std::size_t>(size));
    sh::close(h);
    g_text[got] = '\0';
    char why[160] = "";
    if (!parse_recording(g_text, setup, why, sizeof why)) {
        char line[200];
        std::snprintf(line, sizeof line, "noneuclid firmware: the recording: %s", why);
        return fail(line);
    }
    g_due = kinds::DueEvents<RecordedEvent>(setup.events, static_cast<std::size_t>(setup.count));
    g_frames = setup.frames;
    return true;
}

// The recording's events due by world time `time` (kinds/step.hpp: the program's rule).
int controls(double time, RecordedEvent* out, int room) {
    int n = 0;
    for (const RecordedEvent* e; n < room && (e = g_due.next_due(time));) out[n++] = *e;
    return n;
}

// A frame's file is opened with its first band and closed after its last.
bool present(const uint16_t* rows, int y0, int y1, long frame) {
    static int h = -1;
    if (g_every == 0 || (frame % g_every != 0 && frame != g_frames)) return true;
    if (y0 == 0) {
        char path[400];
        std::snprintf(path, sizeof path, "%s/frame-%06ld.rgb565", g_outdir, frame);
        h = sh::open(path, "wb");
        if (h < 0) return fail("noneuclid firmware: cannot write a frame into OUTDIR (does it exist?).");
    }
    const bool ok = sh::write(h, rows, static_cast<std::size_t>(kWidth) * 2 * static_cast<std::size_t>(y1 - y0));
    if (y1 == kHeight || !ok) sh::close(h), h = -1;
    return ok;
}

bool runs_forever() { return false; }

void finish(bool success, const char* line) {
    sh::print(line);
    sh::print("\n");
    sh::exit(success);
}

}  // namespace noneuclid::mcu::board

// exit() or abort() (an allocation that failed: the heap is full).
extern "C" [[noreturn]] void mcu_stopped(int status) {
    char line[96];
    std::snprintf(line, sizeof line, "noneuclid firmware: stopped with status %d (out of memory, if 134).", status);
    noneuclid::mcu::board::finish(false, line);
}
