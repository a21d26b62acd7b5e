// The ST7789 driver (st7789.hpp). Command numbers and delays from the controller's datasheet
// (Sitronix ST7789VW, section 9: the system function commands).
#include "st7789.hpp"

#include "hal.hpp"

namespace noneuclid::mcu {
namespace {

enum Command : uint8_t {
    swreset = 0x01,  // software reset: wait 5 ms before the next command, 120 ms before SLPOUT
    slpout = 0x11,   // out of sleep: wait 5 ms before the next command, 120 ms before SLPIN
    noron = 0x13,    // normal display mode (not partial)
    invon = 0x21,    // colours inverted: these IPS panels show the true colours so
    dispon = 0x29,
    caset = 0x2A,  // column address window: start and end, 16 bits each, high byte first
    raset = 0x2B,  // row address window
    ramwr = 0x2C,  // the pixels follow, filling the window row by row
    madctl = 0x36,  // memory access order: 0, rows top to bottom, columns left to right, RGB
    colmod = 0x3A,  // interface pixel format: 0x55, 16 bits a pixel (RGB565)
};

}  // namespace

void St7789::command(uint8_t c, const uint8_t* params, int count) {
    hal::pin_write(pins_.cs, false);
    hal::pin_write(pins_.dc, false);
    hal::spi_write(&c, 1);
    if (count > 0) {
        hal::pin_write(pins_.dc, true);
        hal::spi_write(params, static_cast<std::size_t>(count));
    }
    hal::pin_write(pins_.cs, true);
}

void St7789::window(int x0, int y0, int x1, int y1) {
    const uint8_t columns[4] = {static_cast<uint8_t>(x0 >> 8), static_cast<uint8_t>(x0), static_cast<uint8_t>(x1 >> 8),
                                static_cast<uint8_t>(x1)};
    const uint8_t rows[4] = {static_cast<uint8_t>(y0 >> 8), static_cast<uint8_t>(y0), static_cast<uint8_t>(y1 >> 8),
                             static_cast<uint8_t>(y1)};
    command(caset, columns, 4);
    command(raset, rows, 4);
}

void St7789::start() {
    hal::pin_output(pins_.cs, true);
    hal::pin_output(pins_.dc, true);
    hal::pin_output(pins_.backlight, false);
    hal::pin_output(pins_.reset, true);
    hal::spi_begin();
    // A hardware reset (low at least 10 us), then the controller's own.
    hal::delay_ms(1);
    hal::pin_write(pins_.reset, false);
    hal::delay_ms(1);
    hal::pin_write(pins_.reset, true);
    hal::delay_ms(120);
    command(swreset);
    hal::delay_ms(150);
    command(slpout);
    hal::delay_ms(120);
    const uint8_t rgb565 = 0x55, order = 0x00;
    command(colmod, &rgb565, 1);
    command(madctl, &order, 1);
    command(invon);
    command(noron);
    command(dispon);
    hal::delay_ms(10);
    hal::pin_write(pins_.backlight, true);
}

void St7789::draw(const uint16_t* rows, int y0, int y1) {
    if (y0 == 0) {
        window(0, 0, kWidth - 1, kHeight - 1);
        const uint8_t c = ramwr;
        hal::pin_write(pins_.cs, false);
        hal::pin_write(pins_.dc, false);
        hal::spi_write(&c, 1);
        hal::pin_write(pins_.dc, true);
    }
    static uint8_t row[kWidth * 2];  // one row, high bytes first (static: off the small stack)
    for (int y = y0; y < y1; ++y) {
        const uint16_t* from = rows + (y - y0) * kWidth;
        for (int x = 0; x < kWidth; ++x) {
            row[2 * x] = static_cast<uint8_t>(from[x] >> 8);
            row[2 * x + 1] = static_cast<uint8_t>(from[x]);
        }
        hal::spi_write(row, sizeof row);
    }
    if (y1 == kHeight) hal::pin_write(pins_.cs, true);
}

}  // namespace noneuclid::mcu
