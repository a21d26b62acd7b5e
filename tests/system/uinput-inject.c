/* A key device made through /dev/uinput, for the system test of the evdev backend
 * (tests/system/input.sh): a real input device as the kernel sees it, as a USB keyboard or a
 * gpio-key overlay would be.
 *
 *   uinput-inject NAME CODE...     creates NAME with those EV_KEY codes, prints "ready", then
 *                                  reads commands from stdin, one a line:
 *     p CODE   press (value 1)      r CODE   release (value 0)
 *     a CODE   autorepeat (value 2) q        destroy the device and exit (so does EOF)
 *
 * Built static on the host (gcc -static), run in the guest. */
#include <fcntl.h>
#include <linux/uinput.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

static int emit(int fd, unsigned short type, unsigned short code, int value) {
    struct input_event ev;
    memset(&ev, 0, sizeof ev);
    ev.type = type;
    ev.code = code;
    ev.value = value;
    return write(fd, &ev, sizeof ev) == (ssize_t)sizeof ev ? 0 : -1;
}

int main(int argc, char** argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: uinput-inject NAME CODE...\n");
        return 2;
    }
    int fd = open("/dev/uinput", O_WRONLY | O_NONBLOCK);
    if (fd < 0) {
        perror("uinput-inject: /dev/uinput");
        return 1;
    }
    if (ioctl(fd, UI_SET_EVBIT, EV_KEY) < 0) {
        perror("uinput-inject: UI_SET_EVBIT");
        return 1;
    }
    for (int i = 2; i < argc; ++i)
        if (ioctl(fd, UI_SET_KEYBIT, atoi(argv[i])) < 0) {
            perror("uinput-inject: UI_SET_KEYBIT");
            return 1;
        }
    struct uinput_setup setup;
    memset(&setup, 0, sizeof setup);
    setup.id.bustype = BUS_VIRTUAL;
    setup.id.vendor = 0x1234;
    setup.id.product = 0x5678;
    snprintf(setup.name, sizeof setup.name, "%s", argv[1]);
    if (ioctl(fd, UI_DEV_SETUP, &setup) < 0 || ioctl(fd, UI_DEV_CREATE) < 0) {
        perror("uinput-inject: creating the device");
        return 1;
    }
    printf("ready\n");
    fflush(stdout);

    char line[64];
    while (fgets(line, sizeof line, stdin)) {
        char cmd = 0;
        int code = 0;
        if (sscanf(line, " %c %d", &cmd, &code) < 1) continue;
        int value = cmd == 'p' ? 1 : cmd == 'r' ? 0 : cmd == 'a' ? 2 : -1;
        if (cmd == 'q') break;
        if (value < 0) {
            fprintf(stderr, "uinput-inject: unknown command %s", line);
            continue;
        }
        if (emit(fd, EV_KEY, (unsigned short)code, value) < 0 || emit(fd, EV_SYN, SYN_REPORT, 0) < 0)
            perror("uinput-inject: write");
    }
    ioctl(fd, UI_DEV_DESTROY);
    close(fd);
    return 0;
}
