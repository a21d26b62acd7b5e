// The HAL (hal.hpp) on the mps2-an385's Cortex-M3: its CMSDK GPIO block 0 (16 pins) for the
// pins, SPI bit-banged on two of them (clock and data out), delays by counting cycles. On a
// chip with an SPI peripheral (a Pico's, an STM32's) spi_write would hand the row to it (or its
// DMA); the rest of the firmware does not change.
#include "hal.hpp"

#include "mcu-st7789.hpp"

namespace noneuclid::mcu::hal {
namespace {

// The CMSDK GPIO registers (ARM's Cortex-M System Design Kit, the AN385's GPIO 0).
struct Gpio {
    volatile uint32_t data;         // 0x000: the pins' levels
    volatile uint32_t dataout;      // 0x004: the outputs' levels
    uint32_t reserved[2];
    volatile uint32_t outenset;     // 0x010: pins made outputs
    volatile uint32_t outenclr;     // 0x014: pins made inputs
};
Gpio& gpio() { return *reinterpret_cast<Gpio*>(0x40010000u); }

constexpr uint8_t kSpiClock = 0, kSpiData = 1;  // the bit-banged bus's pins
// The outputs' levels as last written: each pin_write is one store of every output's level, not
// a read-modify-write of DATAOUT (so a log of the stores, qemu's -d unimp, is the wire itself).
uint32_t g_out = 0;

}  // namespace

void pin_output(uint8_t pin, bool high) {
    pin_write(pin, high);
    gpio().outenset = 1u << pin;
}

// (The CMSDK block has no pull-ups of its own: the board's resistors hold the buttons high.)
void pin_input_pullup(uint8_t pin) { gpio().outenclr = 1u << pin; }

void pin_write(uint8_t pin, bool high) {
    const uint32_t bit = 1u << pin;
    g_out = high ? g_out | bit : g_out & ~bit;
    gpio().dataout = g_out;
}

bool pin_read(uint8_t pin) { return (gpio().data >> pin) & 1u; }

void spi_begin() {
    pin_output(kSpiClock, false);
    pin_output(kSpiData, false);
}

// Mode 0: data set while the clock is low, taken by the panel on the rising edge.
void spi_write(const uint8_t* data, std::size_t bytes) {
    for (std::size_t i = 0; i < bytes; ++i)
        for (int bit = 7; bit >= 0; --bit) {
            pin_write(kSpiData, (data[i] >> bit) & 1u);
            pin_write(kSpiClock, true);
            pin_write(kSpiClock, false);
        }
}

// About `ms` milliseconds at the board's clock: the loop is some 4 cycles a turn.
void delay_ms(uint32_t ms) {
    for (uint32_t turns = ms * (boards::mcu_st7789::kCoreHz / 4000); turns > 0; --turns) asm volatile("");
}

}  // namespace noneuclid::mcu::hal
