// An LD_PRELOAD shim that makes a regular file look like a framebuffer, with the geometry the
// test asks for: the framebuffer ioctls on a descriptor of the file $FAKE_FB are answered from
// $FAKE_FB_GEOMETRY ("xres yres xoffset yoffset xres_virtual yres_virtual bpp line_length
// smem_len"), an XRGB8888 or RGB565 true-colour mode; every other ioctl goes to the C library.
// The file itself is mapped as the framebuffer's memory (the test sizes it). So noneuclid's
// kiosk can be run against geometries no real driver reports, such as an x offset past the line.
#include <dlfcn.h>
#include <linux/fb.h>
#include <sys/stat.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

bool is_fake(int fd) {
    const char* path = std::getenv("FAKE_FB");
    struct stat a{}, b{};
    return path && fstat(fd, &a) == 0 && stat(path, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

bool fill(unsigned long request, void* arg) {
    unsigned v[9] = {};
    const char* g = std::getenv("FAKE_FB_GEOMETRY");
    if (!g || std::sscanf(g, "%u %u %u %u %u %u %u %u %u", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &v[7],
                          &v[8]) != 9)
        return false;
    if (request == FBIOGET_VSCREENINFO) {
        fb_var_screeninfo var{};
        var.xres = v[0], var.yres = v[1], var.xoffset = v[2], var.yoffset = v[3];
        var.xres_virtual = v[4], var.yres_virtual = v[5], var.bits_per_pixel = v[6];
        if (v[6] == 16)
            var.red = {11, 5, 0}, var.green = {5, 6, 0}, var.blue = {0, 5, 0};
        else
            var.red = {16, 8, 0}, var.green = {8, 8, 0}, var.blue = {0, 8, 0};
        std::memcpy(arg, &var, sizeof var);
    } else {
        fb_fix_screeninfo fix{};
        std::strncpy(fix.id, "fake_fb", sizeof fix.id - 1);
        fix.type = FB_TYPE_PACKED_PIXELS, fix.visual = FB_VISUAL_TRUECOLOR;
        fix.line_length = v[7], fix.smem_len = v[8];
        std::memcpy(arg, &fix, sizeof fix);
    }
    return true;
}

}  // namespace

extern "C" int ioctl(int fd, unsigned long request, ...) {
    va_list ap;
    va_start(ap, request);
    void* arg = va_arg(ap, void*);
    va_end(ap);
    if (is_fake(fd)) {
        if (request == FBIOGET_VSCREENINFO || request == FBIOGET_FSCREENINFO) return fill(request, arg) ? 0 : -1;
        return -1;  // panning, vsync, blanking: not offered
    }
    using Real = int (*)(int, unsigned long, ...);
    static Real real = reinterpret_cast<Real>(dlsym(RTLD_NEXT, "ioctl"));
    return real(fd, request, arg);
}
