// A driver for the ST7789 display controller on a 240x240 RGB565 panel (the common 1.3" IPS
// modules), over the HAL's SPI and pins (hal.hpp): reset, wake and set the pixel format once
// (start), then frames (draw), a band of rows at a time. Write-only: the panel is never read, so MISO is not used.
//
// The wire: a command byte with D/C low, its parameters with D/C high, chip select low around
// each. The frame goes as RAMWR after the address window (CASET, RASET) covering the panel;
// pixels are RGB565 sent high byte first, so the canvas's little-endian words are swapped, a
// row at a time through a row buffer (the frame itself is not copied).
#pragma once

#include <cstdint>

namespace noneuclid::mcu {

struct St7789Pins {
    uint8_t dc;         // data/command: low for a command byte
    uint8_t cs;         // chip select, active low
    uint8_t reset;      // the controller's reset, active low
    uint8_t backlight;  // the panel's backlight, on high
};

class St7789 {
public:
    static constexpr int kWidth = 240, kHeight = 240;

    explicit St7789(const St7789Pins& pins) : pins_(pins) {}
    // The controller reset and set up: awake, 16 bits a pixel (RGB565), rows top to bottom,
    // colours inverted as these IPS panels need, display and backlight on. About 300 ms.
    void start();
    // Rows [y0, y1) of a frame: RGB565 pixels as the canvas holds them (little-endian words,
    // rows `kWidth` pixels apart, row y0 first). A frame's bands come top to bottom: the first
    // (y0 0) opens the window and RAMWR, the last (y1 kHeight) ends it; between them the panel
    // waits, chip select low, for the next band's pixels.
    void draw(const uint16_t* rows, int y0, int y1);

private:
    void command(uint8_t c, const uint8_t* params = nullptr, int count = 0);
    void window(int x0, int y0, int x1, int y1);

    St7789Pins pins_;
};

}  // namespace noneuclid::mcu
