#include "app/displays.hpp"

#include "app/memory_display.hpp"
#include "app/options.hpp"

namespace noneuclid::app {
namespace {

std::unique_ptr<Display> open_x11(const Options& o, const files::Board&, std::string& error) {
    return platform::open_window({o.width, o.height}, error);
}
std::unique_ptr<Display> open_fbdev(const Options& o, const files::Board& b, std::string& error) {
    platform::KioskSpec spec;
    spec.device = o.device, spec.fps = o.fps, spec.board = b, spec.input = o.input;
    return platform::open_kiosk(spec, error);
}
std::unique_ptr<Display> open_png(const Options& o, const files::Board&, std::string&) {
    return std::make_unique<MemoryDisplay>(o.width, o.height, o.format);
}

const DisplayRow kDisplays[] = {
    {platform::DisplayKind::x11, "x11", "a desktop window (the default when DISPLAY is set)", false, open_x11},
    {platform::DisplayKind::fbdev, "fbdev",
     "the kiosk: the framebuffer (fbdev:/dev/fbN names one) and the board's buttons", true, open_fbdev},
    {platform::DisplayKind::png, "png",
     "headless: attract mode flies, the last frame goes to --screenshot (out/run.png)", false, open_png},
};

}  // namespace

const DisplayRow* display_rows(std::size_t& count) {
    count = std::size(kDisplays);
    return kDisplays;
}
const DisplayRow* display_row(platform::DisplayKind kind) {
    for (const DisplayRow& r : kDisplays)
        if (r.kind == kind) return &r;
    return nullptr;
}
const DisplayRow* display_named(const std::string& name) {
    for (const DisplayRow& r : kDisplays)
        if (name == r.name) return &r;
    return nullptr;
}

}  // namespace noneuclid::app
