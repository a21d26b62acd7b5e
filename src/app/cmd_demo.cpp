// `noneuclid demo`: the paper's figures and the kiosk's picture (app/figures.hpp) as PNG files
// in a directory, and where they are. --size is one panel's size.
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "app/commands.hpp"
#include "app/figures.hpp"
#include "app/options.hpp"
#include "app/picture.hpp"
#include "app/setup.hpp"

namespace noneuclid::app {

int demo_command(int argc, char** argv, int first) {
    std::string dir = "out";
    world::EngineKind engine = world::kDefaultEngine;
    int width = 0, height = 0;  // a panel's; 0: each figure's own
    bool hud = true;
    Args args(argc, argv, first);
    while (args.more()) {
        const std::string opt = args.next();
        if (opt == "--out-dir") dir = args.value(opt);
        else if (opt == "--engine") engine = engine_value(opt, args.value(opt));
        else if (opt == "--size") parse_size(opt, args.value(opt), width, height);
        else if (opt == "--no-hud") hud = false;
        else usage_error("unknown option '" + opt + "' for demo; see 'noneuclid --help'.");
    }
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) usage_error("cannot create the directory '" + dir + "': " + ec.message() + ".");
    const platform::LoadedFont font = load_font(defaults(Command::render));
    platform::catch_stop_signals();  // a signal leaves the picture being made as it was
    std::string written;
    for (int i = 0; i < kFigureCount; ++i) {
        const Figure& f = kFigures[i];
        Options o = defaults(Command::render);
        o.hud = hud, o.engine = engine;
        o.width = width > 0 ? width : f.width, o.height = height > 0 ? height : f.height;
        Picture picture;
        const std::string path = dir + "/" + f.name + ".png";
        if (render_figure(f, o, font.font, picture).stopped) {
            std::fprintf(stderr, "noneuclid: stopped by signal %d; %s is left as it was.\n", platform::stop_signal(),
                         path.c_str());
            return 1;
        }
        std::string error;
        if (!platform::write_png(path, picture.canvas, error)) {
            std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
            return 1;
        }
        written += std::string(written.empty() ? "" : ", ") + f.name + ".png (" + f.what + ")";
    }
    std::printf("noneuclid: the demo is in %s/: %s. 'noneuclid --help' lists the commands.\n", dir.c_str(),
                written.c_str());
    return 0;
}

}  // namespace noneuclid::app
