// The framebuffer display and the console guard. See fbdev.hpp.
#include "linux/fbdev.hpp"

#include <fcntl.h>
#include <linux/fb.h>
#include <linux/kd.h>
#include <linux/vt.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "app/platform.hpp"  // monotonic_ns
#include "render/blit.hpp"

namespace noneuclid::platform {
namespace {

std::string errno_text(int e) { return std::strerror(e); }

const char* format_name(const render::PixelFormat& f) {
    using P = render::PixelFormat;
    auto same = [&](const P& o) {
        return f.bits_per_pixel == o.bits_per_pixel && f.red.offset == o.red.offset && f.red.length == o.red.length &&
               f.green.offset == o.green.offset && f.green.length == o.green.length &&
               f.blue.offset == o.blue.offset && f.blue.length == o.blue.length;
    };
    for (const P& o : {P::rgb565(), P::bgr565(), P::xrgb8888(), P::xbgr8888(), P::rgb888(), P::bgr888()})
        if (same(o)) return o.name;
    return "custom";
}

// Why the framebuffer could not be opened, and what to do about it.
std::string open_error(const std::string& path, int e) {
    if (e == ENOENT || e == ENXIO || e == ENODEV)
        return "there is no framebuffer " + path + ": check the device (ls /dev/fb*), enable a display driver with fbdev emulation (on a Pi: dtoverlay=vc4-kms-v3d in config.txt), or use --display x11 or png";
    if (e == EACCES || e == EPERM)
        return "no permission to open the framebuffer " + path + ": add the user to the video group (sudo usermod -aG video $USER, then log in again) or run it as the noneuclid service";
    return "cannot open the framebuffer " + path + " (" + errno_text(e) + "): check that it is a framebuffer device";
}

// What is wrong with the geometry the driver reports, or null. Every number is checked before
// it is used: the picture's rows, from the offsets on, must lie inside the memory that is
// mapped (a driver reporting an xoffset past the line, or a memory size too small, would
// otherwise have the copy write past the mapping). All in 64 bits: the fields are 32-bit.
const char* geometry_fault(const fb_fix_screeninfo& fix, const fb_var_screeninfo& var, uint64_t bpp) {
    const uint64_t w = var.xres, h = var.yres, line = fix.line_length, mem = fix.smem_len;
    const uint64_t row_end = (uint64_t{var.xoffset} + w) * bpp, rows_end = uint64_t{var.yoffset} + h;
    return w == 0 || h == 0              ? "an empty mode"
           : w > 16384 || h > 16384      ? "a mode larger than 16384 pixels a side"
           : line > (uint64_t{1} << 28)  ? "a line length over 256 MiB"
           : row_end > line              ? "rows (with their x offset) longer than a line"
           : rows_end * line > mem       ? "rows (with their y offset) past the end of its memory"
                                         : nullptr;
}

}  // namespace

Fbdev::~Fbdev() {
    if (map_) munmap(map_, map_len_);
    if (fd_ >= 0) ::close(fd_);
}

bool Fbdev::open(const std::string& path, std::string& error) {
    path_ = path;
    fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd_ < 0) {
        error = open_error(path, errno);
        return false;
    }
    fb_fix_screeninfo fix{};
    fb_var_screeninfo var{};
    if (ioctl(fd_, FBIOGET_FSCREENINFO, &fix) != 0 || ioctl(fd_, FBIOGET_VSCREENINFO, &var) != 0) {
        error = path + " does not answer the framebuffer ioctls (" + errno_text(errno) + "): give --display fbdev:/dev/fbN a framebuffer device";
        return false;
    }
    id_.assign(fix.id, strnlen(fix.id, sizeof fix.id));
    format_.bits_per_pixel = static_cast<uint8_t>(var.bits_per_pixel);
    format_.red = {static_cast<uint8_t>(var.red.offset), static_cast<uint8_t>(var.red.length)};
    format_.green = {static_cast<uint8_t>(var.green.offset), static_cast<uint8_t>(var.green.length)};
    format_.blue = {static_cast<uint8_t>(var.blue.offset), static_cast<uint8_t>(var.blue.length)};
    format_.name = format_name(format_);
    const bool truecolor = fix.type == FB_TYPE_PACKED_PIXELS &&
                           (fix.visual == FB_VISUAL_TRUECOLOR || fix.visual == FB_VISUAL_DIRECTCOLOR);
    if (!truecolor || var.grayscale > 1 || var.bits_per_pixel > 32 || !format_.supported() ||
        var.red.msb_right || var.green.msb_right || var.blue.msb_right) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "%s (%s) is %u bits per pixel %s (red %u/%u, green %u/%u, blue %u/%u), and noneuclid draws only "
                      "16, 24 or 32-bit true colour: set a 16- or 32-bit mode (fbset -depth 32, or on a Pi "
                      "framebuffer_depth=32 in config.txt)",
                      path.c_str(), id_.c_str(), var.bits_per_pixel, truecolor ? "true colour" : "palette or planar",
                      var.red.offset, var.red.length, var.green.offset, var.green.length, var.blue.offset,
                      var.blue.length);
        error = text;
        return false;
    }
    const uint64_t w = var.xres, h = var.yres, bpp = static_cast<uint64_t>(format_.bytes_per_pixel());
    const uint64_t line = fix.line_length, mem = fix.smem_len;
    if (const char* wrong = geometry_fault(fix, var, bpp)) {
        char text[320];
        std::snprintf(text, sizeof text,
                      "%s (%s) reports %s (%ux%u at offset %u,%u, virtual %ux%u, %u bits per pixel, line %u bytes, "
                      "memory %u bytes): set a mode with fbset, or check the display driver",
                      path.c_str(), id_.c_str(), wrong, var.xres, var.yres, var.xoffset, var.yoffset, var.xres_virtual,
                      var.yres_virtual, var.bits_per_pixel, fix.line_length, fix.smem_len);
        error = text;
        return false;
    }
    line_length_ = static_cast<std::ptrdiff_t>(line);
    xoffset_ = static_cast<int>(var.xoffset);
    yoffset_ = static_cast<int>(var.yoffset);
    yres_virtual_ = static_cast<int>(std::min<uint64_t>(var.yres_virtual, mem / line));
    map_len_ = fix.smem_len;
    void* m = mmap(nullptr, map_len_, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, 0);
    if (m == MAP_FAILED) {
        map_ = nullptr;
        error = "cannot map the framebuffer " + path + " into memory (" + errno_text(errno) + "): check the display driver";
        return false;
    }
    map_ = static_cast<uint8_t*>(m);
    // Two pages in the virtual screen and the driver pans: draw to the hidden one.
    if (static_cast<uint64_t>(yres_virtual_) >= 2 * h && 2 * h * line <= mem) {
        fb_var_screeninfo pan = var;
        pan.xoffset = 0;
        pan.yoffset = 0;
        pan_ok_ = ioctl(fd_, FBIOPAN_DISPLAY, &pan) == 0;
        if (pan_ok_) xoffset_ = yoffset_ = 0;
    }
    ioctl(fd_, FBIOBLANK, FB_BLANK_UNBLANK);  // failure is fine: not every driver blanks
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(w * bpp);
    back_pixels_.assign(static_cast<std::size_t>(stride) * static_cast<std::size_t>(h), 0);
    back_ = render::Canvas(back_pixels_.data(), static_cast<int>(w), static_cast<int>(h), stride, format_);
    return true;
}

render::Canvas Fbdev::page(int index) const {
    const std::ptrdiff_t row = std::ptrdiff_t{yoffset_} + std::ptrdiff_t{index} * back_.height();
    uint8_t* base = map_ + row * line_length_ + std::ptrdiff_t{xoffset_} * format_.bytes_per_pixel();
    return render::Canvas(base, back_.width(), back_.height(), line_length_, format_);
}

void Fbdev::present() {
    if (pan_ok_) {
        const int hidden = 1 - shown_page_;
        render::copy_canvas(back_, page(hidden));
        fb_var_screeninfo var{};
        if (ioctl(fd_, FBIOGET_VSCREENINFO, &var) == 0) {
            var.xoffset = 0;
            var.yoffset = static_cast<unsigned>(hidden * back_.height());
            if (ioctl(fd_, FBIOPAN_DISPLAY, &var) == 0) {
                shown_page_ = hidden;
                return;
            }
        }
        pan_ok_ = false;  // stopped panning: single page from now on
        render::copy_canvas(back_, page(shown_page_));
        return;
    }
    if (vsync_ok_) {
        uint32_t crtc = 0;
        const int64_t asked = monotonic_ns();
        if (ioctl(fd_, FBIO_WAITFORVSYNC, &crtc) != 0) {
            vsync_ok_ = false;  // ENOTTY, EBUSY: pace by the clock
        } else {
            // A driver that answers at once without waiting would let the loop run flat out:
            // three instant answers in a row and the clock paces instead.
            const bool instant = monotonic_ns() - asked < 300000;
            instant_vsyncs_ = instant ? instant_vsyncs_ + 1 : 0;
            if (instant_vsyncs_ >= 3) vsync_ok_ = false;
        }
    }
    render::copy_canvas(back_, page(shown_page_));
}

render::Canvas Fbdev::read_back(std::vector<uint8_t>& pixels) const {
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(back_.width()) * format_.bytes_per_pixel();
    pixels.assign(static_cast<std::size_t>(stride) * static_cast<std::size_t>(back_.height()), 0);
    const render::Canvas copy(pixels.data(), back_.width(), back_.height(), stride, format_);
    render::copy_canvas(page(shown_page_), copy);
    return copy;
}

std::string Fbdev::describe() const {
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s: %s, %dx%d, %d bpp %s (red %d/%d, green %d/%d, blue %d/%d), line %td bytes, offset %d,%d, "
                  "virtual height %d, %s",
                  path_.c_str(), id_.empty() ? "(no id)" : id_.c_str(), back_.width(), back_.height(),
                  format_.bits_per_pixel, format_.name, format_.red.offset, format_.red.length, format_.green.offset,
                  format_.green.length, format_.blue.offset, format_.blue.length, line_length_, xoffset_, yoffset_,
                  yres_virtual_, pan_ok_ ? "two pages, panning" : "one page (copy per frame)");
    return text;
}

// ---- the console -----------------------------------------------------------------------

namespace {

// Saved at start, restored at exit or from a signal handler (so: plain globals, and only
// async-signal-safe calls in restore).
int g_tty = -1;
long g_kd_mode = KD_TEXT;
vt_mode g_vt_mode{};
termios g_termios{};
bool g_have_termios = false;
volatile std::sig_atomic_t g_restored = 1;

void restore_console() {
    if (g_restored) return;
    g_restored = 1;
    ioctl(g_tty, KDSETMODE, g_kd_mode);
    ioctl(g_tty, VT_SETMODE, &g_vt_mode);
    if (g_have_termios) tcsetattr(g_tty, TCSANOW, &g_termios);
    static const char show_cursor[] = "\033[?25h";
    if (write(g_tty, show_cursor, sizeof show_cursor - 1) < 0) {
    }
}

void on_crash(int sig) {
    restore_console();
    signal(sig, SIG_DFL);
    raise(sig);
}

}  // namespace

ConsoleGuard::ConsoleGuard() {
    catch_stop_signals();  // the loop then ends, and the destructor restores the console
    long mode = 0;
    if (!isatty(STDIN_FILENO) || ioctl(STDIN_FILENO, KDGETMODE, &mode) != 0) {
        note = "stdin is not a virtual console, so the console is left as it is (fbcon may draw its cursor over the picture; the service runs on tty1)";
        return;
    }
    g_tty = STDIN_FILENO;
    g_kd_mode = mode;
    ioctl(g_tty, VT_GETMODE, &g_vt_mode);
    g_have_termios = tcgetattr(g_tty, &g_termios) == 0;
    g_restored = 0;
    struct sigaction crash{};
    crash.sa_handler = on_crash;
    sigemptyset(&crash.sa_mask);
    for (int s : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) sigaction(s, &crash, nullptr);
    if (ioctl(g_tty, KDSETMODE, KD_GRAPHICS) != 0) {
        note = "could not put the console in graphics mode (" + errno_text(errno) + "): text may show through";
    } else {
        note = "console in graphics mode (restored at exit)";
    }
    if (g_have_termios) {
        termios raw = g_termios;
        raw.c_lflag &= static_cast<tcflag_t>(~(ECHO | ICANON));
        tcsetattr(g_tty, TCSANOW, &raw);
    }
    static const char hide_cursor[] = "\033[?25l";
    if (write(g_tty, hide_cursor, sizeof hide_cursor - 1) < 0) {
    }
}

ConsoleGuard::~ConsoleGuard() { restore_console(); }

bool ConsoleGuard::owned() const { return g_tty >= 0; }

}  // namespace noneuclid::platform
