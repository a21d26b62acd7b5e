#include "web_display.hpp"

#include <emscripten.h>

// The page's side (platform/web/page/page.js sets Module.noneuclidPresent and
// Module.noneuclidReadBack): put RGBA bytes on the <canvas>, and read them back from it.
// clang-format off
EM_JS(void, nw_js_present, (const uint8_t* rgba, int width, int height), {
    Module.noneuclidPresent(rgba, width, height);
});
EM_JS(int, nw_js_read_back, (uint8_t* rgba, int width, int height), {
    return Module.noneuclidReadBack(rgba, width, height) ? 1 : 0;
});
// clang-format on

namespace noneuclid::web {

WebDisplay::WebDisplay(int width, int height, render::PixelFormat format) : format_(format) { resize(width, height); }

void WebDisplay::resize(int width, int height) {
    const render::PixelFormat format = format_;
    const render::PixelFormat rgba = render::PixelFormat::rgba8888();
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    rgba_.assign(pixels * 4, 0);
    drawn_.clear();
    if (format.byte_channels()) {
        canvas_ = render::Canvas(rgba_.data(), width, height, std::ptrdiff_t{width} * 4, rgba);
        return;
    }
    drawn_.assign(pixels * static_cast<std::size_t>(format.bytes_per_pixel()), 0);
    canvas_ = render::Canvas(drawn_.data(), width, height, std::ptrdiff_t{width} * format.bytes_per_pixel(), format);
}

void WebDisplay::present() {
    if (!drawn_.empty()) {  // another format: its colours, as render would write them to a PNG
        const render::Canvas out(rgba_.data(), canvas_.width(), canvas_.height(), std::ptrdiff_t{canvas_.width()} * 4,
                                 render::PixelFormat::rgba8888());
        for (int y = 0; y < canvas_.height(); ++y)
            for (int x = 0; x < canvas_.width(); ++x) out.set(x, y, canvas_.get(x, y));
    }
    nw_js_present(rgba_.data(), canvas_.width(), canvas_.height());
}

bool WebDisplay::wait(int64_t, app::InputSink& sink) {
    for (int i = 0; i < queued_; ++i) sink.input(queue_[i]);
    queued_ = 0;
    return true;
}

void WebDisplay::queue(world::InputEvent e) {
    if (queued_ == kQueue) return;  // more than a frame can hold: a stuck key repeating; dropped
    queue_[queued_++] = e;
}

bool WebDisplay::read_back(app::Picture& out, std::string& error) {
    const int w = canvas_.width(), h = canvas_.height();
    out.pixels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 0);
    if (!nw_js_read_back(out.pixels.data(), w, h)) {
        error = "cannot read the page's canvas back (getImageData failed).";
        return false;
    }
    out.canvas = render::Canvas(out.pixels.data(), w, h, std::ptrdiff_t{w} * 4, render::PixelFormat::rgba8888());
    return true;
}

}  // namespace noneuclid::web
