// The display of a web page (app/display.hpp): frames drawn into memory of the WebAssembly
// module and put on the page's <canvas> with putImageData, the page's keys and touch buttons as
// input. The page's requestAnimationFrame drives the frame loop one tick at a time and so paces
// it to the screen's refresh; the display never sleeps.
#pragma once

#include <cstdint>
#include <vector>

#include "app/display.hpp"

namespace noneuclid::web {

class WebDisplay final : public app::Display {
public:
    // A canvas of width x height pixels in `format` (what a recording or --format asks for):
    // drawn straight into the page's RGBA bytes when the format's colours are bytes of a 32-bit
    // word (xrgb8888 gives the same pixels as RGBA8888), else drawn in `format` and converted
    // for the page as it is shown, so that every format shows the pixels `render` writes.
    WebDisplay(int width, int height, render::PixelFormat format);
    // From the page: the canvas is width x height pixels from the next frame on (the page's space
    // changed: a turned phone, full screen). Allocates, once per change, as a window's resize does.
    void resize(int width, int height);

    render::Canvas canvas() override { return canvas_; }
    void present() override;
    bool wait(int64_t deadline_ns, app::InputSink& sink) override;
    bool closing() const override { return closing_; }
    bool paced_by_refresh() const override { return true; }
    bool read_back(app::Picture& out, std::string& error) override;
    std::string stats_note() const override { return "the page's canvas (putImageData)"; }
    const char* legend() const override { return "keys"; }

    // From the page: a key or touch button pressed or released; delivered by the next wait().
    void queue(world::InputEvent e);
    // From the page: the run ends after the frame being drawn.
    void close() { closing_ = true; }

private:
    static constexpr int kQueue = 256;

    std::vector<uint8_t> rgba_;   // what the page's canvas gets: R, G, B, A bytes
    std::vector<uint8_t> drawn_;  // the frame in the asked-for format, when that is not RGBA's
    render::PixelFormat format_;
    render::Canvas canvas_;
    world::InputEvent queue_[kQueue];
    int queued_ = 0;
    bool closing_ = false;
};

}  // namespace noneuclid::web
