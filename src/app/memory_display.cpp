#include "app/memory_display.hpp"


namespace noneuclid::app {

MemoryDisplay::MemoryDisplay(int width, int height, render::PixelFormat format) {
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(width) * format.bytes_per_pixel();
    pixels_.assign(static_cast<std::size_t>(stride) * static_cast<std::size_t>(height), 0);
    canvas_ = render::Canvas(pixels_.data(), width, height, stride, format);
}

bool MemoryDisplay::read_back(Picture& out, std::string&) {
    out.pixels = pixels_;
    out.canvas = render::Canvas(out.pixels.data(), canvas_.width(), canvas_.height(), canvas_.stride(), canvas_.format());
    return true;
}

}  // namespace noneuclid::app
