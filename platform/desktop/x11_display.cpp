// The desktop window (Xlib + MIT-SHM) and `noneuclid run`'s loop. See x11_window.hpp.
#include "desktop/x11_window.hpp"

#include <X11/XKBlib.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>
#include <X11/keysym.h>
#include <sys/ipc.h>
#include <sys/shm.h>
#include <time.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <utility>

#if NONEUCLID_HAVE_DESKTOP
#include "desktop/console_font.hpp"
#endif
#if NONEUCLID_HAVE_PNG
#include "desktop/png_file.hpp"
#endif
#include "render/session.hpp"
#include "run_stats.hpp"
#include "world/controls.hpp"
#include "world/world.hpp"

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

double now_seconds() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
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

    // Opens the display and the window; on failure prints one sentence and returns the status.
    int open(int w, int h) {
        const char* name = std::getenv("DISPLAY");
        dpy = XOpenDisplay(nullptr);
        if (!dpy) {
            std::fprintf(stderr, "noneuclid: cannot open the X display '%s': start an X server (or set DISPLAY to a running one), or use --display png.\n",
                         name ? name : "");
            return 2;
        }
        XSetIOErrorHandler(lost_server);
        const int screen = DefaultScreen(dpy);
        visual = DefaultVisual(dpy, screen);
        depth = DefaultDepth(dpy, screen);
        if (visual->c_class != TrueColor || (depth != 24 && depth != 32)) {
            std::fprintf(stderr, "noneuclid: the X display's default visual is %d-bit %s, and noneuclid draws only into 24- or 32-bit TrueColor: run the X server at depth 24 (e.g. Xvfb -screen 0 1024x768x24).\n",
                         depth, visual->c_class == TrueColor ? "TrueColor" : "non-TrueColor");
            return 2;
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
        if (!create_image(w, h)) return 2;
        XMapWindow(dpy, win);
        XEvent ev;
        do {  // blocks until the window is on screen (the screenshot needs it viewable)
            XWindowEvent(dpy, win, StructureNotifyMask, &ev);
            if (ev.type == ConfigureNotify) pending_w = ev.xconfigure.width, pending_h = ev.xconfigure.height;
        } while (ev.type != MapNotify);
        return 0;
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
    bool create_image(int w, int h) {
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
                std::fprintf(stderr, "noneuclid: Xlib could not make a %dx%d image for the window: make the window smaller.\n", w, h);
                return false;
            }
            image->byte_order = LSBFirst;  // our words are little-endian; Xlib converts if the server differs
            image->data = static_cast<char*>(std::malloc(static_cast<std::size_t>(image->bytes_per_line) * static_cast<std::size_t>(h)));
            if (!image->data) {
                XDestroyImage(image);
                image = nullptr;
                std::fprintf(stderr, "noneuclid: out of memory for a %dx%d window image: make the window smaller.\n", w, h);
                return false;
            }
        }
        render::PixelFormat format;
        if (!format_of(*image, format)) {
            std::fprintf(stderr, "noneuclid: the X display's pixels are %d bits with masks %06lx/%06lx/%06lx, which the canvas cannot draw: run the X server at depth 24 TrueColor.\n",
                         image->bits_per_pixel, image->red_mask, image->green_mask, image->blue_mask);
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

    // The window's contents read back from the X server, written as a PNG.
    int screenshot(const std::string& path) {
#if NONEUCLID_HAVE_PNG
        g_x_error = false;
        XErrorHandler old = XSetErrorHandler(note_x_error);
        XImage* shot = XGetImage(dpy, win, 0, 0, static_cast<unsigned>(width), static_cast<unsigned>(height), AllPlanes, ZPixmap);
        XSync(dpy, False);
        XSetErrorHandler(old);
        if (!shot || g_x_error) {
            if (shot) XDestroyImage(shot);
            std::fprintf(stderr, "noneuclid: the X server would not give the window's contents back for %s: keep the window mapped and on screen until noneuclid exits.\n",
                         path.c_str());
            return 1;
        }
        render::PixelFormat format;
        if (!format_of(*shot, format)) {
            std::fprintf(stderr, "noneuclid: the X server's %d-bit pixels cannot be written to %s: run the X server at depth 24 TrueColor.\n",
                         shot->bits_per_pixel, path.c_str());
            XDestroyImage(shot);
            return 1;
        }
        if (shot->byte_order == MSBFirst) {  // big-endian words: reverse each pixel's bytes
            const int bpp = shot->bits_per_pixel / 8;
            for (int y = 0; y < shot->height; ++y) {
                auto* p = reinterpret_cast<unsigned char*>(shot->data) + static_cast<std::ptrdiff_t>(y) * shot->bytes_per_line;
                for (int x = 0; x < shot->width; ++x, p += bpp)
                    for (int i = 0; i < bpp / 2; ++i) std::swap(p[i], p[bpp - 1 - i]);
            }
        }
        const render::Canvas c(shot->data, shot->width, shot->height, shot->bytes_per_line, format);
        std::string error;
        const bool ok = write_png(path, c, error);
        XDestroyImage(shot);
        if (!ok) {
            std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
            return 1;
        }
        std::fprintf(stderr, "noneuclid: wrote %s (%dx%d, read back from the X server)\n", path.c_str(), width, height);
        return 0;
#else
        std::fprintf(stderr, "noneuclid: this build has no PNG support, so --screenshot %s cannot be written: install libpng-dev and rebuild.\n",
                     path.c_str());
        return 1;
#endif
    }
};

// What a key does: a held action, or a one-shot command.
enum class Key { none, quit, k_minus1, k_zero, k_plus1, projection, hud, reset, action };

Key key_of(KeySym s, world::Action& action) {
    using world::Action;
    switch (s) {
        case XK_Escape: return Key::quit;
        case XK_Up: case XK_w: case XK_W: case XK_KP_Up: action = Action::thrust; return Key::action;
        case XK_Left: case XK_a: case XK_A: case XK_KP_Left: action = Action::turn_left; return Key::action;
        case XK_Right: case XK_d: case XK_D: case XK_KP_Right: action = Action::turn_right; return Key::action;
        case XK_plus: case XK_equal: case XK_bracketright: case XK_KP_Add: action = Action::curvature_up; return Key::action;
        case XK_minus: case XK_bracketleft: case XK_KP_Subtract: action = Action::curvature_down; return Key::action;
        case XK_1: case XK_KP_1: return Key::k_minus1;
        case XK_2: case XK_KP_2: return Key::k_zero;
        case XK_3: case XK_KP_3: return Key::k_plus1;
        case XK_p: case XK_P: return Key::projection;
        case XK_h: case XK_H: return Key::hud;
        case XK_r: case XK_R: return Key::reset;
        default: return Key::none;
    }
}

template <class W>
int run_loop(X11Window& x, const world::Scene& scene, const RunOptions& o) {
    using T = typename W::scalar;
#if NONEUCLID_HAVE_DESKTOP
    const LoadedFont loaded = default_hud_font(nullptr);
    const render::Font& font = loaded.font;
#else
    const render::Font& font = render::builtin_font();
#endif
    render::SessionOptions so;
    so.draw.projection = o.projection;
    so.draw.antialias = o.antialias;
    so.hud = o.hud;
    so.scene_name = scene.name.c_str();
    so.controls = kDesktopControls;
    render::Session<W> session(scene, so, font);
    W& world = session.world;
    bool quit = false;
    const long period_ns = static_cast<long>(1e9 / o.fps + 0.5);
    timespec next{};
    clock_gettime(CLOCK_MONOTONIC, &next);
    const double start = now_seconds();
    double fps_since = start;
    long fps_frames = 0, frames = 0;
    while (!quit && (o.frames == 0 || frames < o.frames)) {
        while (XPending(x.dpy)) {
            XEvent ev;
            XNextEvent(x.dpy, &ev);
            if (ev.type == KeyPress || ev.type == KeyRelease) {
                world::Action action{};
                const Key k = key_of(XLookupKeysym(&ev.xkey, 0), action);
                const auto control = static_cast<world::Control>(action);  // the same order
                if (ev.type == KeyRelease) {
                    if (k == Key::action) session.control({control, false});
                    continue;
                }
                switch (k) {
                    case Key::quit: quit = true; break;
                    case Key::action: session.control({control, true}); break;
                    case Key::k_minus1: world.K = T(-1); break;
                    case Key::k_zero: world.K = T(0); break;
                    case Key::k_plus1: world.K = T(1); break;
                    case Key::projection: session.control({world::Control::projection, true}); break;
                    case Key::hud: session.control({world::Control::hud, true}); break;
                    case Key::reset:
                        session.control({world::Control::reset, true});
                        session.control({world::Control::reset, false});
                        break;
                    case Key::none: break;
                }
            } else if (ev.type == ConfigureNotify) {
                x.pending_w = ev.xconfigure.width, x.pending_h = ev.xconfigure.height;
            } else if (ev.type == ClientMessage && static_cast<Atom>(ev.xclient.data.l[0]) == x.wm_delete) {
                quit = true;
            }
        }
        if (quit) break;
        if (x.pending_w > 0 && (x.pending_w != x.width || x.pending_h != x.height)) {
            if (!x.create_image(x.pending_w, x.pending_h)) return 2;
        }
        session.frame(x.canvas);
        x.show();
        ++frames, ++fps_frames;
        const double t = now_seconds();
        if (t - fps_since >= 0.5) session.fps = static_cast<double>(fps_frames) / (t - fps_since), fps_since = t, fps_frames = 0;

        // Pacing: sleep until the next frame's deadline; after a stall, start again from now
        // rather than racing to catch up.
        next.tv_nsec += period_ns;
        while (next.tv_nsec >= 1000000000L) next.tv_nsec -= 1000000000L, ++next.tv_sec;
        timespec now{};
        clock_gettime(CLOCK_MONOTONIC, &now);
        const double late = static_cast<double>(now.tv_sec - next.tv_sec) + static_cast<double>(now.tv_nsec - next.tv_nsec) * 1e-9;
        if (late > static_cast<double>(period_ns) * 1e-9) next = now;
        while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr) == EINTR) {
        }
    }

    int status = 0;
    if (!o.screenshot.empty()) status = x.screenshot(o.screenshot);
    if (o.stats) print_run_stats(frames, now_seconds() - start, x.using_shm ? "MIT-SHM" : "XPutImage");
    return status;
}

}  // namespace

int run_x11(const world::Scene& scene, const RunOptions& o) {
    X11Window x;
    if (const int rc = x.open(o.width, o.height); rc != 0) return rc;
    if (o.engine == "double") return run_loop<world::World<double>>(x, scene, o);
    if (o.engine == "float") return run_loop<world::World<float>>(x, scene, o);
    if (o.engine == "paper") return run_loop<world::World<double, true>>(x, scene, o);
    return run_loop<world::World<fx::fixed>>(x, scene, o);
}

}  // namespace noneuclid::platform
