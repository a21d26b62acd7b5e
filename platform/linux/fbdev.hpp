// The Linux framebuffer (fbdev) as a display: the device's format read from
// FBIOGET_VSCREENINFO / FBIOGET_FSCREENINFO (16, 24 or 32 bpp, any channel offsets), rows
// stepped by line_length, xoffset/yoffset honoured; the world drawn into a RAM back buffer and
// copied to the mapped framebuffer once per frame (render::copy_canvas). When the virtual
// screen holds two pages and FBIOPAN_DISPLAY works, the copy goes to the hidden page and the
// display pans to it; FBIO_WAITFORVSYNC is used when the driver answers it. Neither is counted
// on: DRM's fbdev emulation usually offers neither (docs/kiosk.md).
//
// The console: if stdin is a virtual terminal, it is put in KD_GRAPHICS (fbcon stops drawing
// text and the cursor) with echo off, and restored on exit (SIGINT/TERM/HUP/QUIT ask the loop
// to stop: platform::catch_stop_signals) and on crash signals (SEGV/BUS/ILL/FPE/ABRT, after
// which the signal is re-raised). The screen is
// unblanked at start.
#pragma once

#include <csignal>
#include <cstdint>
#include <string>
#include <vector>

#include "render/canvas.hpp"

namespace noneuclid::platform {

class Fbdev {
public:
    Fbdev() = default;
    Fbdev(const Fbdev&) = delete;
    Fbdev& operator=(const Fbdev&) = delete;
    ~Fbdev();

    // Opens and maps the device; on failure returns false with one sentence in `error`.
    bool open(const std::string& path, std::string& error);
    // "/dev/fb0: vc4drmfb, 800x480, 16 bpp rgb565 (r 11/5 g 5/6 b 0/5), line 1600 bytes, ..."
    std::string describe() const;

    const render::Canvas& back() const { return back_; }  // draw here
    void present();                                         // copy to the screen (pan/vsync if working)
    bool vsync() const { return vsync_ok_; }                // FBIO_WAITFORVSYNC worked so far
    // What the screen shows: the shown page, copied out of the framebuffer's memory.
    render::Canvas read_back(std::vector<uint8_t>& pixels) const;
    int width() const { return back_.width(); }
    int height() const { return back_.height(); }

private:
    render::Canvas page(int index) const;

    std::string path_, id_;
    int fd_ = -1;
    uint8_t* map_ = nullptr;
    std::size_t map_len_ = 0;
    std::ptrdiff_t line_length_ = 0;
    int xoffset_ = 0, yoffset_ = 0, yres_virtual_ = 0;
    render::PixelFormat format_;
    std::vector<uint8_t> back_pixels_;
    render::Canvas back_;
    bool pan_ok_ = false, vsync_ok_ = true;
    int shown_page_ = 0;
    int instant_vsyncs_ = 0;
};

// The virtual terminal on stdin, owned for the program's life (see above). Safe to construct
// when stdin is not a VT: it then does nothing and says so in `note`.
class ConsoleGuard {
public:
    ConsoleGuard();
    ~ConsoleGuard();
    ConsoleGuard(const ConsoleGuard&) = delete;
    ConsoleGuard& operator=(const ConsoleGuard&) = delete;
    bool owned() const;
    std::string note;  // one line for the start-up log
};

}  // namespace noneuclid::platform
