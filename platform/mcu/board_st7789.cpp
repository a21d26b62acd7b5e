// The ST7789 board (board.hpp, boards/mcu-st7789.hpp): the display through the driver of
// st7789.hpp, four buttons read once a frame (a change since the last frame is a press or a
// release: a frame is 1/60 s, longer than a button's bounce), the game running until power off.
#include "board.hpp"
#include "hal.hpp"
#include "mcu-st7789.hpp"
#include "st7789.hpp"

namespace noneuclid::mcu::board {
namespace {

namespace pins = boards::mcu_st7789;

St7789 g_display({pins::kDisplayDc, pins::kDisplayCs, pins::kDisplayReset, pins::kDisplayBacklight});
bool g_held[4] = {};

}  // namespace

bool start(Recording& setup) {
    setup = Recording{};
    static_assert(sizeof pins::kScene <= sizeof setup.scene);
    for (int i = 0; pins::kScene[i] != '\0'; ++i) setup.scene[i] = pins::kScene[i];
    setup.aa = pins::kAntialias;
    setup.hud = pins::kHud;
    for (const pins::Button& b : pins::kButtons) hal::pin_input_pullup(b.pin);
    g_display.start();
    return true;
}

int controls(double, RecordedEvent* out, int room) {
    int n = 0;
    for (int i = 0; i < 4 && n < room; ++i) {
        const bool down = !hal::pin_read(pins::kButtons[i].pin);  // (pulled up: low is pressed)
        if (down == g_held[i]) continue;
        g_held[i] = down;
        out[n].pressed = down, out[n].tap = false, out[n].control = pins::kButtons[i].control;
        ++n;
    }
    return n;
}

bool present(const uint16_t* rows, int y0, int y1, long) {
    g_display.draw(rows, y0, y1);
    return true;
}

bool runs_forever() { return true; }

// (Reached only if the world cannot be made: the screen stays dark.)
void finish(bool, const char*) {
    for (;;) {
    }
}

}  // namespace noneuclid::mcu::board

// exit() or abort() (an allocation that failed): as finish.
extern "C" [[noreturn]] void mcu_stopped(int) {
    for (;;) {
    }
}
