// `noneuclid dump` (a scene's state as JSON Lines, one line a frame) and `noneuclid render`
// (its last frame as a PNG).
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "app/commands.hpp"
#include "app/picture.hpp"
#include "app/setup.hpp"

namespace noneuclid::app {

namespace {
bool put(const std::string& line) {
    return std::fwrite(line.data(), 1, line.size(), stdout) == line.size();
}
int write_failed() {
    std::fprintf(stderr, "noneuclid: cannot write the dump to standard output (%s): check where it goes.\n",
                 std::strerror(errno));
    return 1;
}
}  // namespace

int dump_command(int argc, char** argv, int first) {
    Script script;
    const Options o = layered_options(argc, argv, first, Command::dump, script);
    const world::Scene scene = load_scene(o);
    Options plain = o;
    plain.attract = 0, plain.threads = 1, plain.hud = false;
    const std::unique_ptr<Session> s =
        make_session(o.engine, scene, session_options(plain, scene, o.legend), render::builtin_font(), nullptr);
    ScriptPlayer player(script.events);
    std::string line;
    s->play_due(player);
    s->dump(o.width, o.height, line);
    if (!put(line)) return write_failed();
    for (long f = 0; f < o.frames; ++f) {
        s->step();
        s->play_due(player);
        line.clear();
        s->dump(o.width, o.height, line);
        if (!put(line)) return write_failed();
    }
    return std::fflush(stdout) == 0 ? 0 : write_failed();
}

int render_command(int argc, char** argv, int first) {
    Script script;
    const Options o = layered_options(argc, argv, first, Command::render, script);
    if (o.out.empty()) usage_error("render needs --out FILE.png: where to write the picture.");
    const world::Scene scene = load_scene(o);
    const platform::LoadedFont font = load_font(o);
    platform::catch_stop_signals();  // a signal leaves --out as it was (render_picture, write_png)
    Picture picture;
    const PictureResult r = render_picture(o, scene, &script, font.font, picture);
    if (r.stopped) {
        std::fprintf(stderr, "noneuclid: stopped by signal %d after %ld frames; %s is left as it was.\n",
                     platform::stop_signal(), r.frame, o.out.c_str());
        return 1;
    }
    std::string error;
    if (!platform::write_png(o.out, picture.canvas, error)) {
        std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
        return 1;
    }
    std::fprintf(stderr, "noneuclid: wrote %s (%dx%d, %s, K = %.3f, frame %ld)\n", o.out.c_str(), o.width, o.height,
                 o.format.name, r.K, r.frame);
    return 0;
}

}  // namespace noneuclid::app
