// The microcontroller board (docs/microcontroller.md): a Cortex-M3 class chip, an ST7789 240x240
// RGB565 display on SPI and four buttons to ground, wired to the pins named here (the chip's
// GPIO numbers, as the HAL of platform/mcu/hal.hpp takes them). platform/mcu/board_st7789.cpp
// reads it; a board wired otherwise changes only this file.
//
// The four buttons play the game: left and right turn, thrust, fire. (fire also starts a game.)
// The scene is the game's; anti-aliasing is off, as on the kiosk boards of boards/*.toml at this
// size: the aliased frame is the one near the instruction budget (docs/microcontroller.md).
#pragma once

#include <cstdint>

#include "world/action.hpp"

namespace noneuclid::boards::mcu_st7789 {

inline constexpr const char* kScene = "asteroids";
inline constexpr bool kAntialias = false;
inline constexpr bool kHud = true;  // the score, lives and level (English, the built-in font)

// The display: SPI's clock and data pins are the HAL's (hal::spi_begin); these are the others.
inline constexpr uint8_t kDisplayDc = 2, kDisplayCs = 3, kDisplayReset = 4, kDisplayBacklight = 5;

struct Button {
    uint8_t pin;              // to ground when pressed; the pin's pull-up holds it high
    world::Action control;
};
inline constexpr Button kButtons[4] = {
    {8, world::Action::left},
    {9, world::Action::right},
    {10, world::Action::thrust},
    {11, world::Action::fire},
};

// The core's clock, for the HAL's delays.
inline constexpr uint32_t kCoreHz = 25000000;

}  // namespace noneuclid::boards::mcu_st7789
