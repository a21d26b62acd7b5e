// What the app asks of the platform, as functions each platform implements (raylib's split:
// the core declares them, a platform file defines them). platform/ holds the definitions; a
// backend that is not built gets a stub that says so in one sentence, so the command line needs
// no #if. Declarations only: no OS header here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/display.hpp"
#include "app/sound.hpp"
#include "render/canvas.hpp"
#include "render/font.hpp"
#include "files/board.hpp"
#include "world/image.hpp"

namespace noneuclid::platform {

// ---- the clock and the process (platform/posix) -------------------------------------------

// A monotonic clock in nanoseconds: what Display::wait's deadlines speak.
int64_t monotonic_ns();
// CPU seconds this process has used so far.
struct CpuTime {
    double user = 0, system = 0;
};
CpuTime cpu_time();
// Whether standard error is a terminal (where a long run shows its progress).
bool stderr_is_terminal();
// At start: a write past the file-size limit (RLIMIT_FSIZE), or into a pipe whose reader has
// gone (`noneuclid dump | head`), fails with an error the program reports, instead of SIGXFSZ or
// SIGPIPE ending it silently halfway through.
void prepare_process();
// From now on SIGINT, SIGTERM, SIGHUP and SIGQUIT ask the program to stop instead of ending it:
// stop_signal() then says which came (0: none yet), and waits (poll, sleep) end early.
void catch_stop_signals();
int stop_signal();

// The user's locale for messages: the first of $LC_ALL, $LC_MESSAGES and $LANG that is set and
// not empty ("de_DE.UTF-8"), or "" (the web page passes the browser's language as --lang).
std::string locale_name();

// ---- which display `run` uses when not told ------------------------------------------------

enum class DisplayKind { x11, fbdev, png };
struct DisplayChoice {
    DisplayKind display = DisplayKind::png;
    std::string reason;  // "because ..." for the one line the program prints
};
// An X11 window when $DISPLAY is set, the framebuffer when /dev/fb0 exists and stdin is a
// terminal (a console), the headless PNG display otherwise.
DisplayChoice choose_display();

// ---- displays -------------------------------------------------------------------------------

struct WindowSpec {
    int width = 800, height = 480;  // the window's first size
};
// The X11 window (platform/x11/x11_display.cpp). Null, with one sentence in `error`, when it
// cannot be opened or this build has none.
std::unique_ptr<app::Display> open_window(const WindowSpec& spec, std::string& error);

struct KioskSpec {
    std::string device = "/dev/fb0";  // the framebuffer
    double fps = 60;                  // the loop's cap: vsync paces only at >= 55
    files::Board board;               // the buttons (GPIO lines, evdev keys)
    std::string input = "auto";       // gpio, evdev, none or auto
};
// The kiosk (platform/linux/kiosk_display.cpp): the framebuffer, the console it owns, the
// board's GPIO buttons and evdev keys. Prints what it opened, one line each, on stderr.
std::unique_ptr<app::Display> open_kiosk(const KioskSpec& spec, std::string& error);

// ---- sound (docs/sound.md) --------------------------------------------------------------

struct SoundSpec {
    std::string device = "default";  // an ALSA PCM name
    int rate = 44100;                // samples a second, mono, 16 bits
};
// The game's sound (platform/linux/alsa_sound.cpp: ALSA; the page's is its own). It renders each
// frame's world time of sound and never blocks: what does not fit the device's buffer is
// dropped. Null, with one sentence in `error`, when the device cannot be opened or this build
// has no sound; the run then goes on silent.
std::unique_ptr<app::SoundOut> open_sound(const SoundSpec& spec, std::string& error);

// ---- files ----------------------------------------------------------------------------------

// What the program finds at a path, without following a symbolic link there (lstat).
enum class FileKind { missing, regular, directory, symlink, fifo, device, socket, other };
// "a directory", "a symbolic link", "a pipe (FIFO)", "a device", ...
const char* file_kind_name(FileKind kind);

// Whether an output file (--out, --gif, --record, --screenshot, demo's pictures) may be written
// at `path`, decided as AtomicFile::open decides: nothing there yet, or a regular file (replaced
// whole, keeping its mode); a FIFO, or this program's own standard output by any name
// (/dev/stdout, /dev/fd/1), is written into. Anything else is never replaced nor written: a
// directory, a device, a socket, a symbolic link. False with one sentence naming `path`.
bool output_allowed(const std::string& path, std::string& error);

// A file written whole or not at all (platform/posix/atomic_file.cpp): into a temporary file
// beside `path`, then flushed, synced to the disk and renamed over `path` by commit(). Until
// then `path` is untouched; abort(), a failed commit() or the destructor remove the temporary
// file. A replaced file keeps its permissions. A crash leaves at most a hidden temporary file
// (.NAME.noneuclid-XXXXXX, locked while its writer lives), never a half-written NAME, and the
// next write of NAME removes the ones whose writer is gone. A target output_allowed() refuses
// is refused here too; a FIFO or the program's standard output is written into as a stream
// (commit() flushes it; there is nothing to rename, and a failed write leaves what was written).
class AtomicFile {
public:
    AtomicFile() = default;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    ~AtomicFile() { abort(); }

    // False with one sentence in `error` (naming `path`, ending with the fix).
    bool open(const std::string& path, std::string& error);
    std::FILE* file() const { return file_; }
    bool commit(std::string& error);
    void abort();

private:
    std::string path_, temp_;
    std::FILE* file_ = nullptr;
    [[maybe_unused]] bool stream_ = false;  // written into (a FIFO, standard output): no temporary file (POSIX only: the web platform has no such files)
};

// Files the program keeps and shares between processes (the high-score table,
// platform/posix/kept_file.cpp).
//
// Reads `path` whole if it is a regular file, at most `limit` + 1 bytes (so a caller can tell
// a file over `limit`). A symbolic link is not followed and nothing but a regular file is
// opened (a FIFO is never waited on). `kind` says what is there; false with one sentence (no
// path, no full stop) in `error` when it is not a regular file or cannot be read.
bool read_kept_file(const std::string& path, std::size_t limit, std::string& out, FileKind& kind, std::string& error);
// Renames the regular file `path` to `path` + `suffix`, or if that exists to `path` + `suffix`
// + ".2", ".3", ... (up to ".99"), never over an existing file. The name used in `aside`; false
// with one sentence (no full stop) in `error`.
bool set_aside(const std::string& path, const std::string& suffix, std::string& aside, std::string& error);
// An exclusive lock (flock) on the directory of `path`, held while the object lives: the
// processes that share a file there take turns to read, change and write it. Waited for up to
// five seconds; then busy() is true and held() false. held() is false too when the directory
// cannot be opened (the caller goes on unlocked).
class DirectoryLock {
public:
    explicit DirectoryLock(const std::string& path);
    ~DirectoryLock();
    DirectoryLock(const DirectoryLock&) = delete;
    DirectoryLock& operator=(const DirectoryLock&) = delete;
    bool held() const { return fd_ >= 0; }
    bool busy() const { return busy_; }

private:
    int fd_ = -1;
    bool busy_ = false;
};

// The path of a file the program keeps between runs (the game's high scores): in the
// service's state directory ($STATE_DIRECTORY, which systemd's StateDirectory= sets), else in
// $XDG_STATE_HOME/noneuclid, else ~/.local/state/noneuclid, made if missing. "" with one sentence
// (no full stop) in `error` when there is none.
std::string state_file(const std::string& name, std::string& error);

// Writes `canvas` to `path` as an 8-bit RGB PNG, atomically (AtomicFile): a full disk, an
// error or a stop signal (stop_signal()) while writing leaves `path` as it was. False with one
// sentence in `error`.
bool write_png(const std::string& path, const render::Canvas& canvas, std::string& error);
// Writes `pages` as a PDF, one page each of width_pt x height_pt points filled by its image
// (8-bit RGB, Flate-compressed with zlib: platform/files/pdf_file.cpp), atomically as
// write_png writes. False with one sentence in `error`.
bool write_pdf(const std::string& path, const std::vector<render::Canvas>& pages, double width_pt, double height_pt,
               std::string& error);
// Reads an 8-bit RGB or RGBA PNG into `rgb` (3 bytes a pixel, rows packed).
bool read_png(const std::string& path, int& width, int& height, std::string& rgb, std::string& error);
// Reads a PNG file as a texture (any PNG colour type and depth; alpha is ignored): at most
// world::kImageFileLimit bytes, and its header checked before the image is decoded, so that an
// image over world::kImageMaxSide texels either way is refused without being decoded. False
// with one sentence (no full stop, the path in it) in `why`: missing, not a PNG file,
// truncated or damaged, too large.
bool read_texture(const std::string& path, world::Image& out, std::string& why);
// The identity of the file at `path` (its device and inode, the link followed), "" if it cannot
// be found: a texture named by two spellings of one file's path ("a.png", "./a.png", a link) is
// decoded once (files::FileIdentity).
std::string file_identity(const std::string& path);

// An animated GIF written frame by frame (platform/files/gif_file.cpp, giflib), whole or not
// at all as write_png writes (AtomicFile): `path` is untouched until finish() succeeds, and a
// failed write, a stop signal (stop_signal()) or a writer destroyed unfinished leave it as it
// was. Every frame has the writer's size and its own colour table: its colours exactly when
// there are at most 256, else giflib's median-cut quantisation of them. It loops for ever.
class GifWriter {
public:
    virtual ~GifWriter() = default;
    // Adds a frame shown for `centiseconds` (0 to 65535: a GIF's delay is 16 bits); false with
    // one sentence in `error`.
    virtual bool frame(const render::Canvas& c, int centiseconds, std::string& error) = 0;
    virtual bool finish(std::string& error) = 0;
};
// Null with one sentence in `error` (naming `path`, ending with the fix) if it cannot be opened,
// or this build has no giflib.
std::unique_ptr<GifWriter> open_gif(const std::string& path, int width, int height, std::string& error);
// Reads an animated GIF back: its size, and each frame as 8-bit RGB (3 bytes a pixel, rows
// packed) with its delay in centiseconds. For the tests.
struct GifFrame {
    std::string rgb;
    int centiseconds = 0;
};
bool read_gif(const std::string& path, int& width, int& height, std::vector<GifFrame>& frames, std::string& error);

// A font with the bytes it points into (move-only: font.glyphs points into bytes).
struct LoadedFont {
    std::vector<uint8_t> bytes;
    render::Font font;
    std::string source;  // the file's path, or "built-in 6x8"

    LoadedFont() = default;
    LoadedFont(LoadedFont&&) noexcept = default;
    LoadedFont& operator=(LoadedFont&&) noexcept = default;
    LoadedFont(const LoadedFont&) = delete;
    LoadedFont& operator=(const LoadedFont&) = delete;
};
// The HUD's font. `choice`: "builtin", a PSF file (gzip-compressed or not), or "" for the
// default: $NONEUCLID_FONT if set, else a Terminus or Fixed console font from
// /usr/share/consolefonts, else the built-in one. False with one sentence in `error` when a
// font asked for by name cannot be read; the default never fails.
bool hud_font(const std::string& choice, LoadedFont& out, std::string& error);

// ---- the kiosk's board and buttons (platform/linux) --------------------------------------

// `spec` is a board file's path or a board name (rpi4, generic, ...); "" detects the board from
// the machine's device-tree model (generic when none matches); then the board override
// (/etc/noneuclid/board.toml, platform/linux/boards.hpp) over it. `note` says which and why.
bool find_board(const std::string& spec, files::Board& out, std::string& note, std::string& error);

// `noneuclid buttons`: prints each press and release of the board's buttons (`input`: gpio,
// evdev or auto) to stdout, "press thrust", until `events` events (0: no limit) or `timeout`
// seconds (0: none). Returns the exit status; errors are one sentence on stderr.
int print_buttons(const files::Board& board, const std::string& input, long events, double timeout);

}  // namespace noneuclid::platform
