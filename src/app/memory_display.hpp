// The headless display: frames drawn into memory, nobody watching, no input. `noneuclid run
// --display png` runs on it and writes the last frame as a PNG (the frame loop's screenshot);
// tests run the frame loop on it.
#pragma once

#include <vector>

#include "app/display.hpp"

namespace noneuclid::app {

class MemoryDisplay final : public Display {
public:
    MemoryDisplay(int width, int height, render::PixelFormat format);

    render::Canvas canvas() override { return canvas_; }
    void present() override { ++presented_; }
    bool wait(int64_t, InputSink&) override { return true; }
    bool closing() const override { return false; }
    bool realtime() const override { return false; }
    bool read_back(Picture& out, std::string& error) override;
    const char* legend() const override { return "buttons"; }

    long presented() const { return presented_; }

private:
    std::vector<uint8_t> pixels_;
    render::Canvas canvas_;
    long presented_ = 0;
};

}  // namespace noneuclid::app
