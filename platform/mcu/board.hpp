// What a board gives the firmware (firmware.cpp): where the frames go and where the controls
// come from. Two boards implement it:
//   board_qemu.cpp    qemu-system-arm's mps2-an385 under semihosting: a recording read from a
//                     host file, the frames written to host files (the emulation test, tests/mcu);
//   board_st7789.cpp  a board with an ST7789 240x240 SPI display and four buttons
//                     (boards/mcu-st7789.hpp), through the HAL of hal.hpp.
#pragma once

#include <cstdint>

#include "recording.hpp"

namespace noneuclid::mcu::board {

inline constexpr int kWidth = 240, kHeight = 240;  // the display's pixels, RGB565

// Once, before the world is made: what to play. False (the reason said) stops the firmware.
bool start(Recording& setup);
// The controls that came in before world time `time` (pressed or released), at most `room`;
// how many. A recording's are its events due by then; buttons', the changes since the last call.
int controls(double time, RecordedEvent* out, int room);
// Rows [y0, y1) of frame `frame` are drawn in `rows` (RGB565, kWidth a row, row y0 first): a
// frame comes as bands, top to bottom. False stops the firmware (the display failed).
bool present(const uint16_t* rows, int y0, int y1, long frame);
// Whether the firmware stops after `frames` frames (a recording's end) or runs on.
bool runs_forever();
// The end: what happened, in one line, and success or failure.
[[noreturn]] void finish(bool success, const char* line);

}  // namespace noneuclid::mcu::board
