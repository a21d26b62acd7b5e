// The desktop window as a display (app/display.hpp): plain Xlib, MIT-SHM when the server
// offers it (XPutImage otherwise), a canvas whose memory is the XImage's buffer, the keys as
// controls, waiting for events on the X connection until the frame is due.
#include <X11/XKBlib.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>
#include <X11/keysym.h>
#include <poll.h>
#include <sys/ipc.h>
#include <sys/shm.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>

#include "app/platform.hpp"

namespace noneuclid::platform {
namespace {

// Set by the temporary error handler around requests that may fail (XShmAttach, XGetImage).
bool g_x_error = false;
int note_x_error(::Display*, XErrorEvent*) {
    g_x_error = true;
    return 0;
}
int lost_server(::Display*) {
    std::fprintf(stderr, "noneuclid: lost the connection to the X server: restart it (or the desktop) and run noneuclid again.\n");
    std::exit(1);
}

render::Channel channel_of(unsigned long mask) {
    render::Channel c;
    if (mask == 0) return c;
    const int offset = __builtin_ctzl(mask);
    const unsigned long bits = mask >> offset;
    if ((bits & (bits + 1)) != 0) return c;  // not contiguous: length 0, unsupported
    c.offset = static_cast<uint8_t>(offset);
    c.length = static_cast<uint8_t>(__builtin_popcountl(mask));
    return c;
}

// The canvas format of an XImage (its bits per pixel, the visual's masks), little-endian words.
bool format_of(const XImage& image, render::PixelFormat& f) {
    f.bits_per_pixel = static_cast<uint8_t>(image.bits_per_pixel);
    f.red = channel_of(image.red_mask);
    f.green = channel_of(image.green_mask);
    f.blue = channel_of(image.blue_mask);
    f.name = "x11";
    return (image.bits_per_pixel == 24 || image.bits_per_pixel == 32) && f.supported();
}

class X11Window {
public:
    ::Display* dpy = nullptr;
    ::Window win = 0;
    GC gc = nullptr;
    Visual* visual = nullptr;
    int depth = 0;
    Atom wm_delete = 0;
    bool shm_available = false;
    bool using_shm = false;
    XShmSegmentInfo shm{};
    XImage* image = nullptr;
    render::Canvas canvas;
    int width = 0, height = 0;

    ~X11Window() {
        if (!dpy) return;
        destroy_image();
        if (gc) XFreeGC(dpy, gc);
        if (win) XDestroyWindow(dpy, win);
        XCloseDisplay(dpy);
    }

    // Opens the display and the window; on failure false, with one sentence in `error`.
    bool open(int w, int h, std::string& error) {
        const char* name = std::getenv("DISPLAY");
        dpy = XOpenDisplay(nullptr);
        if (!dpy) {
            error = std::string("cannot open the X display '") + (name ? name : "") +
                    "': start an X server (or set DISPLAY to a running one), or use --display png.";
            return false;
        }
        XSetIOErrorHandler(lost_server);
        const int screen = DefaultScreen(dpy);
        visual = DefaultVisual(dpy, screen);
        depth = DefaultDepth(dpy, screen);
        if (visual->c_class != TrueColor || (depth != 24 && depth != 32)) {
            error = "the X display's default visual is " + std::to_string(depth) + "-bit " +
                    (visual->c_class == TrueColor ? "TrueColor" : "non-TrueColor") +
                    ", and noneuclid draws only into 24- or 32-bit TrueColor: run the X server at depth 24 (e.g. "
                    "Xvfb -screen 0 1024x768x24).";
            return false;
        }
        int major = 0, minor = 0;
        Bool pixmaps = False;
        shm_available = XShmQueryExtension(dpy) && XShmQueryVersion(dpy, &major, &minor, &pixmaps);
        Bool detectable = False;
        XkbSetDetectableAutoRepeat(dpy, True, &detectable);  // auto-repeat: presses only, no release pairs

        win = XCreateSimpleWindow(dpy, RootWindow(dpy, screen), 0, 0, static_cast<unsigned>(w),
                                  static_cast<unsigned>(h), 0, BlackPixel(dpy, screen), BlackPixel(dpy, screen));
        XSetWindowBackgroundPixmap(dpy, win, None);  // we repaint every frame: no flash on resize
        XStoreName(dpy, win, "noneuclid");
        XClassHint cls{const_cast<char*>("noneuclid"), const_cast<char*>("noneuclid")};
        XSetClassHint(dpy, win, &cls);
        XSizeHints hints{};
        hints.flags = PMinSize;
        hints.min_width = hints.min_height = 16;
        XSetWMNormalHints(dpy, win, &hints);
        wm_delete = XInternAtom(dpy, "WM_DELETE_WINDOW", False);
        XSetWMProtocols(dpy, win, &wm_delete, 1);
        XSelectInput(dpy, win, KeyPressMask | KeyReleaseMask | StructureNotifyMask | ExposureMask);
        gc = XCreateGC(dpy, win, 0, nullptr);
        if (!create_image(w, h, error)) return false;
        XMapWindow(dpy, win);
        XEvent ev;
        do {  // blocks until the window is on screen (the screenshot needs it viewable)
            XWindowEvent(dpy, win, StructureNotifyMask, &ev);
            if (ev.type == ConfigureNotify) pending_w = ev.xconfigure.width, pending_h = ev.xconfigure.height;
        } while (ev.type != MapNotify);
        return true;
    }

    int pending_w = 0, pending_h = 0;  // the size the last ConfigureNotify asked for

    void destroy_image() {
        if (!image) return;
        if (using_shm) {
            XShmDetach(dpy, &shm);
            XSync(dpy, False);
            image->data = nullptr;
            XDestroyImage(image);
            shmdt(shm.shmaddr);
        } else {
            XDestroyImage(image);  // frees the malloc'd pixels too
        }
        image = nullptr;
        canvas = render::Canvas();
    }

    // A shared-memory image if the server takes one, else a client-side image for XPutImage.
    bool create_image(int w, int h, std::string& error) {
        destroy_image();
        using_shm = false;
        if (shm_available) {
            image = XShmCreateImage(dpy, visual, static_cast<unsigned>(depth), ZPixmap, nullptr, &shm,
                                    static_cast<unsigned>(w), static_cast<unsigned>(h));
            if (image && image->byte_order == LSBFirst) {
                shm.shmid = shmget(IPC_PRIVATE, static_cast<std::size_t>(image->bytes_per_line) * static_cast<std::size_t>(h),
                                   IPC_CREAT | 0600);
                void* addr = shm.shmid >= 0 ? shmat(shm.shmid, nullptr, 0) : reinterpret_cast<void*>(-1);
                if (addr != reinterpret_cast<void*>(-1)) {
                    shm.shmaddr = image->data = static_cast<char*>(addr);
                    shm.readOnly = False;
                    g_x_error = false;
                    XErrorHandler old = XSetErrorHandler(note_x_error);
                    XShmAttach(dpy, &shm);
                    XSync(dpy, False);
                    XSetErrorHandler(old);
                    shmctl(shm.shmid, IPC_RMID, nullptr);  // freed once both sides detach
                    if (!g_x_error) using_shm = true;
                    else shmdt(addr);
                } else if (shm.shmid >= 0) {
                    shmctl(shm.shmid, IPC_RMID, nullptr);
                }
            }
            if (!using_shm) {
                if (image) image->data = nullptr, XDestroyImage(image);
                image = nullptr;
                shm_available = false;  // a remote or restricted server: plain XPutImage from now on
            }
        }
        if (!image) {
            image = XCreateImage(dpy, visual, static_cast<unsigned>(depth), ZPixmap, 0, nullptr,
                                 static_cast<unsigned>(w), static_cast<unsigned>(h), 32, 0);
            if (!image) {
                error = "Xlib could not make a " + std::to_string(w) + "x" + std::to_string(h) +
                        " image for the window: make the window smaller.";
                return false;
            }
            image->byte_order = LSBFirst;  // our words are little-endian; Xlib converts if the server differs
            image->data = static_cast<char*>(std::malloc(static_cast<std::size_t>(image->bytes_per_line) * static_cast<std::size_t>(h)));
            if (!image->data) {
                XDestroyImage(image);
                image = nullptr;
                error = "out of memory for a " + std::to_string(w) + "x" + std::to_string(h) +
                        " window image: make the window smaller.";
                return false;
            }
        }
        render::PixelFormat format;
        if (!format_of(*image, format)) {
            char masks[64];
            std::snprintf(masks, sizeof masks, "%06lx/%06lx/%06lx", image->red_mask, image->green_mask, image->blue_mask);
            error = "the X display's pixels are " + std::to_string(image->bits_per_pixel) + " bits with masks " + masks +
                    ", which the canvas cannot draw: run the X server at depth 24 TrueColor.";
            destroy_image();
            return false;
        }
        width = w, height = h;
        canvas = render::Canvas(image->data, w, h, image->bytes_per_line, format);
        return true;
    }

    void show() {
        if (using_shm)
            XShmPutImage(dpy, win, gc, image, 0, 0, 0, 0, static_cast<unsigned>(width), static_cast<unsigned>(height), False);
        else
            XPutImage(dpy, win, gc, image, 0, 0, 0, 0, static_cast<unsigned>(width), static_cast<unsigned>(height));
        XSync(dpy, False);  // the server has read the pixels before we draw the next frame into them
    }

    // The window's contents read back from the X server.
    bool read_back(app::Picture& out, std::string& error) {
        g_x_error = false;
        XErrorHandler old = XSetErrorHandler(note_x_error);
        XImage* shot = XGetImage(dpy, win, 0, 0, static_cast<unsigned>(width), static_cast<unsigned>(height), AllPlanes, ZPixmap);
        XSync(dpy, False);
        XSetErrorHandler(old);
        if (!shot || g_x_error) {
            if (shot) XDestroyImage(shot);
            error = "the X server would not give the window's contents back: keep the window mapped and on screen until noneuclid exits.";
            return false;
        }
        render::PixelFormat format;
        if (!format_of(*shot, format)) {
            error = "the X server's " + std::to_string(shot->bits_per_pixel) +
                    "-bit pixels cannot be read back: run the X server at depth 24 TrueColor.";
            XDestroyImage(shot);
            return false;
        }
        const int bpp = shot->bits_per_pixel / 8;
        out.pixels.assign(static_cast<std::size_t>(shot->bytes_per_line) * static_cast<std::size_t>(shot->height), 0);
        std::memcpy(out.pixels.data(), shot->data, out.pixels.size());
        if (shot->byte_order == MSBFirst) {  // big-endian words: reverse each pixel's bytes
            for (int y = 0; y < shot->height; ++y) {
                uint8_t* p = out.pixels.data() + static_cast<std::ptrdiff_t>(y) * shot->bytes_per_line;
                for (int x = 0; x < shot->width; ++x, p += bpp)
                    for (int i = 0; i < bpp / 2; ++i) std::swap(p[i], p[bpp - 1 - i]);
            }
        }
        out.canvas = render::Canvas(out.pixels.data(), shot->width, shot->height, shot->bytes_per_line, format);
        XDestroyImage(shot);
        return true;
    }
};

// The action a key is, if any: the keys of the action table (world/action.hpp), a printable
// character being its own keysym (X11's Latin-1 keysyms are the characters' codes), a word an
// X11 keysym name.
bool control_of(KeySym s, world::Action& c) {
    for (int i = 0; i < world::kActionCount; ++i) {
        const bool is = world::any_key(i, [&](std::string_view word) {
            const KeySym sym = word.size() == 1 ? static_cast<KeySym>(static_cast<unsigned char>(word[0]))
                                                : XStringToKeysym(std::string(word).c_str());
            return sym != NoSymbol && sym == s;
        });
        if (is) return c = static_cast<world::Action>(i), true;
    }
    return false;
}

class X11Display final : public app::Display {
public:
    bool open(int w, int h, std::string& error) { return x_.open(w, h, error); }

    render::Canvas canvas() override { return x_.canvas; }
    void present() override { x_.show(); }
    bool wait(int64_t deadline_ns, app::InputSink& sink) override {
        for (;;) {
            while (XPending(x_.dpy)) {
                XEvent ev;
                XNextEvent(x_.dpy, &ev);
                world::Action c{};
                if ((ev.type == KeyPress || ev.type == KeyRelease) && control_of(XLookupKeysym(&ev.xkey, 0), c)) {
                    sink.input({c, ev.type == KeyPress});
                } else if (ev.type == ConfigureNotify) {
                    x_.pending_w = ev.xconfigure.width, x_.pending_h = ev.xconfigure.height;
                } else if (ev.type == ClientMessage && static_cast<Atom>(ev.xclient.data.l[0]) == x_.wm_delete) {
                    closed_ = true;
                }
            }
            std::string error;
            if (x_.pending_w > 0 && (x_.pending_w != x_.width || x_.pending_h != x_.height) &&
                !x_.create_image(x_.pending_w, x_.pending_h, error)) {
                std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
                return false;
            }
            const int64_t now = monotonic_ns();
            if (closed_ || now >= deadline_ns || stop_signal()) return true;
            pollfd fd{ConnectionNumber(x_.dpy), POLLIN, 0};
            const int64_t ms = (deadline_ns - now + 999999) / 1000000;
            if (poll(&fd, 1, static_cast<int>(ms > 1000 ? 1000 : ms)) < 0 && errno != EINTR) {
                std::fprintf(stderr, "noneuclid: waiting for the X server failed (%s): restart noneuclid.\n",
                             std::strerror(errno));
                return false;
            }
        }
    }
    bool closing() const override { return closed_; }
    bool read_back(app::Picture& out, std::string& error) override { return x_.read_back(out, error); }
    std::string stats_note() const override { return x_.using_shm ? "MIT-SHM" : "XPutImage"; }
    const char* legend() const override { return "keys"; }

private:
    X11Window x_;
    bool closed_ = false;
};

}  // namespace

std::unique_ptr<app::Display> open_window(const WindowSpec& spec, std::string& error) {
    auto d = std::make_unique<X11Display>();
    if (!d->open(spec.width, spec.height, error)) return nullptr;
    return d;
}

}  // namespace noneuclid::platform
