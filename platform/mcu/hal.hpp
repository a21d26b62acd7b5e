// The hardware the ST7789 board needs, in a few functions (the HAL): pins by number, a blocking
// SPI transmitter, a delay. A port to a chip implements these with its vendor's registers or
// SDK, and nothing else changes; hal_mps2.cpp implements them for the mps2-an385 (the CMSDK GPIO
// block, SPI bit-banged on its pins), so that the ST7789 firmware links and its size is real.
//
// Pins: numbers as the chip's GPIO knows them (boards/mcu-st7789.hpp names them). SPI: mode 0,
// most significant bit first, chip select driven by the driver through a pin (so one SPI bus
// can serve other devices).
#pragma once

#include <cstddef>
#include <cstdint>

namespace noneuclid::mcu::hal {

void pin_output(uint8_t pin, bool high);  // a push-pull output, driven to `high` at once
void pin_input_pullup(uint8_t pin);       // an input with its pull-up (a button to ground)
void pin_write(uint8_t pin, bool high);
bool pin_read(uint8_t pin);
void spi_begin();                                // the bus, its pins set up (once)
void spi_write(const uint8_t* data, std::size_t bytes);  // returns when the last bit is out
void delay_ms(uint32_t ms);

}  // namespace noneuclid::mcu::hal
