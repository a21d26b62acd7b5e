# shellcheck shell=dash
# (busybox sh, an ash, runs it; shellcheck 0.9 checks ash as dash.)
# Guest script of `tests/system/run smoke`: the harness itself, with busybox alone.
# The bochs framebuffer is XRGB8888 800x480, vfb is RGB565 800x480, a gpio-sim bank
# "noneuclid-sim" of 9 lines goes live and its pulls move the line values.

bochs=$(fb_by_name bochs-drmdrmfb) || bochs=""
vfb=$(fb_by_name "Virtual FB") || vfb=""
for fb in /sys/class/graphics/fb[0-9]*; do echo "$fb: $(cat "$fb/name")"; done
check "bochs framebuffer present" [ -n "$bochs" ]
check "vfb framebuffer present" [ -n "$vfb" ]

if [ -n "$bochs" ]; then
    info=$(probe fb "$bochs")
    echo "$bochs: $info"
    check "bochs is fb0" [ "$bochs" = /dev/fb0 ]
    check "bochs 800x480" contains "$info" " xres=800 yres=480 "
    check "bochs XRGB8888" contains "$info" " bpp=32 " " red=16/8 green=8/8 blue=0/8 "
    fb_dump "$bochs" /out/bochs
    check "bochs dump size" [ "$(wc -c < /out/bochs.raw)" -eq $((480 * $(sed -n 's/.* line_length=\([0-9]*\) .*/\1/p' /out/bochs.info))) ]
fi
if [ -n "$vfb" ]; then
    info=$(probe fb "$vfb")
    echo "$vfb: $info"
    check "vfb 800x480" contains "$info" " xres=800 yres=480 "
    check "vfb 16 bpp, red at 0 (what vfb gives)" contains "$info" " bpp=16 " " red=0/5 green=5/6 blue=11/5 "
fi

check "gpio-sim chip live" sim_chip noneuclid-sim 9
echo "gpio-sim: $SIM_DEV, lines in $SIM_DIR"
check "gpiochip device node" [ -c "$SIM_DEV" ]
check "line 4 high when pulled up" [ "$(sim_value 4)" = 1 ]
sim_pull 4 pull-down
check "line 4 low when pulled down" [ "$(sim_value 4)" = 0 ]
sim_pull 4 pull-up
check "line 4 high again" [ "$(sim_value 4)" = 1 ]
check "VT mode of tty1 readable" probe kdmode /dev/tty1
echo "tty1: $(probe kdmode /dev/tty1)"
exit "$FAILS"
