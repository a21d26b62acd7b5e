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
    Options given = defaults(Command::demo);
    Args args(argc, argv, first);
    parse_options(args, given, Command::demo);
    const std::string& dir = given.out_dir;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) usage_error("cannot create the directory '" + dir + "': " + ec.message() + ".");
    const platform::LoadedFont font = load_font(defaults(Command::render));
    platform::catch_stop_signals();  // a signal leaves the picture being made as it was
    std::string written;  // the pictures' names
    int count = 0;
    for (int i = 0; i < kFigureCount; ++i) {
        const Figure& f = kFigures[i];
        Options o = defaults(Command::render);
        o.hud = given.hud, o.engine = given.engine;
        o.width = given.size_given ? given.width : f.width, o.height = given.size_given ? given.height : f.height;
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
        written += std::string(written.empty() ? "" : " ") + f.name + ".png";
        ++count;
    }
    // One short line: the count and the folder (what each shows: docs/design.md, the figures).
    std::printf("noneuclid: the demo wrote %d pictures to %s/ (%s); 'noneuclid --help' lists the commands.\n", count,
                dir.c_str(), written.c_str());
    return 0;
}

}  // namespace noneuclid::app
