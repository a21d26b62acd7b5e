/* A small static tool for the guest of the system test (tests/system/run builds it with
 * `gcc -static`): busybox has no fbset, and nothing in it reads a VT's KD mode.
 *
 *   probe fb /dev/fbN      one line: id, geometry, stride and channel layout as the kernel
 *                          reports them (FBIOGET_FSCREENINFO / FBIOGET_VSCREENINFO), e.g.
 *                          id=bochsdrmfb xres=800 yres=480 xoffset=0 yoffset=0 bpp=32
 *                          line_length=3200 red=16/8 green=8/8 blue=0/8 smem_len=1536000
 *   probe kdmode /dev/ttyN prints "text" or "graphics" (KDGETMODE)
 *
 * Exit 0 on success, 1 with one sentence on stderr otherwise. */
#include <errno.h>
#include <fcntl.h>
#include <linux/fb.h>
#include <linux/kd.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

static int fail(const char* what, const char* path) {
    fprintf(stderr, "probe: %s %s: %s\n", what, path, strerror(errno));
    return 1;
}

int main(int argc, char** argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: probe fb /dev/fbN | probe kdmode /dev/ttyN\n");
        return 2;
    }
    const char* path = argv[2];
    int fd = open(path, O_RDONLY | O_NOCTTY);
    if (fd < 0) return fail("cannot open", path);
    if (strcmp(argv[1], "fb") == 0) {
        struct fb_fix_screeninfo fix;
        struct fb_var_screeninfo var;
        if (ioctl(fd, FBIOGET_FSCREENINFO, &fix) != 0) return fail("FBIOGET_FSCREENINFO on", path);
        if (ioctl(fd, FBIOGET_VSCREENINFO, &var) != 0) return fail("FBIOGET_VSCREENINFO on", path);
        char id[sizeof fix.id + 1];
        memcpy(id, fix.id, sizeof fix.id);
        id[sizeof fix.id] = 0;
        for (char* p = id; *p; ++p)
            if (*p == ' ') *p = '_';
        printf("id=%s xres=%u yres=%u xoffset=%u yoffset=%u bpp=%u line_length=%u red=%u/%u green=%u/%u "
               "blue=%u/%u smem_len=%u\n",
               id, var.xres, var.yres, var.xoffset, var.yoffset, var.bits_per_pixel, fix.line_length,
               var.red.offset, var.red.length, var.green.offset, var.green.length, var.blue.offset,
               var.blue.length, fix.smem_len);
    } else if (strcmp(argv[1], "kdmode") == 0) {
        int mode = -1;
        if (ioctl(fd, KDGETMODE, &mode) != 0) return fail("KDGETMODE on", path);
        printf("%s\n", mode == KD_GRAPHICS ? "graphics" : mode == KD_TEXT ? "text" : "other");
    } else {
        fprintf(stderr, "probe: unknown command '%s' (fb or kdmode)\n", argv[1]);
        return 2;
    }
    close(fd);
    return 0;
}
