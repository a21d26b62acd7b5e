#include "app/options.hpp"

#include "world/quote.hpp"

namespace noneuclid::app {

namespace {
constexpr unsigned bit(Command c) { return 1u << static_cast<unsigned>(c); }
constexpr unsigned kDump = bit(Command::dump), kRender = bit(Command::render), kRun = bit(Command::run);
constexpr unsigned kWorld = kDump | kRender | kRun, kPicture = kRender | kRun;

std::string legend_value(const std::string& opt, const std::string& text) {
    if (text != "keys" && text != "buttons") usage_error(opt + " must be keys or buttons, not '" + text + "'.");
    return text;
}
std::string input_value(const std::string& opt, const std::string& text) {
    if (text != "auto" && text != "gpio" && text != "evdev" && text != "none")
        usage_error(opt + " must be auto, gpio, evdev or none, not '" + text + "'.");
    return text;
}
void display_value(const std::string& text, Options& o) {
    o.display = text, o.device.clear();
    if (text.rfind("fbdev:", 0) == 0) {
        o.display = "fbdev", o.device = text.substr(6);
        if (o.device.empty()) usage_error("--display fbdev: needs a device after the colon, e.g. fbdev:/dev/fb1.");
    }
    if (o.display != "x11" && o.display != "fbdev" && o.display != "png")
        usage_error("--display must be x11, fbdev, fbdev:/dev/fbN or png, not '" + text + "'.");
}
}  // namespace

world::EngineKind engine_value(const std::string& opt, const std::string& text) {
    world::EngineKind e;
    if (!world::parse_engine(text, e)) usage_error(opt + " must be " + world::or_list(world::engine_names()) + ", not '" + text + "'.");
    return e;
}

const char* command_name(Command c) {
    switch (c) {
        case Command::dump: return "dump";
        case Command::render: return "render";
        case Command::run: return "run";
    }
    return "?";
}

Options defaults(Command c) {
    Options o;
    if (c == Command::run) o.frames = 0, o.hud = true;
    return o;
}

bool parse_option(Args& a, const std::string& opt, Options& o, Command c) {
    const unsigned me = bit(c);
    auto is = [&](const char* name, unsigned commands) { return opt == name && (commands & me); };
    if (is("--scene", kWorld)) o.scene = a.value(opt);
    else if (is("--curvature", kWorld)) o.has_curvature = true, o.curvature = a.number(opt, -1, 1);
    else if (is("--engine", kWorld)) o.engine = engine_value(opt, a.value(opt));
    else if (is("--actions", kWorld)) o.actions = a.value(opt);
    else if (is("--projection", kWorld)) o.projection = parse_projection(opt, a.value(opt));
    else if (is("--bodies", kWorld)) o.params.bodies = static_cast<int>(a.count(opt, 1, 100000));
    else if (is("--vertices", kWorld)) o.params.vertices = static_cast<int>(a.count(opt, 1, 10000));
    else if (is("--tessellation", kWorld)) o.params.tessellation = static_cast<int>(a.count(opt, 1, 256));
    else if (is("--frames", kWorld)) o.frames = static_cast<long>(a.count(opt, c == Command::run ? 1 : 0, 100000000));
    else if (is("--dt", kDump | kRender)) o.dt = a.number(opt, 1e-4, 1);
    else if (is("--size", kWorld)) parse_size(opt, a.value(opt), o.width, o.height), o.size_given = true;
    else if (is("--format", kPicture)) o.format = parse_format(opt, a.value(opt));
    else if (is("--aa", kPicture)) o.aa = true;
    else if (is("--no-aa", kPicture)) o.aa = false;
    else if (is("--hud", kPicture)) o.hud = true;
    else if (is("--no-hud", kPicture)) o.hud = false;
    else if (is("--font", kPicture)) o.font = a.value(opt);
    else if (is("--legend", kPicture)) o.legend = legend_value(opt, a.value(opt));
    else if (is("--best", kPicture)) o.best = static_cast<long>(a.count(opt, 0, 1000000000)), o.best_given = true;
    else if (is("--scores", kRun)) o.scores = a.value(opt);
    else if (is("--width", kRender)) o.line_width = a.number(opt, 0.1, 64);
    else if (is("--timelapse", kRender)) o.timelapse = static_cast<long>(a.count(opt, 1, 100000000));
    else if (is("--timelapse-grids", kRender)) o.timelapse_grids = static_cast<long>(a.count(opt, 1, 100000000));
    else if (is("--out", kRender)) o.out = a.value(opt);
    else if (is("--gif", kRender)) o.gif = a.value(opt);
    else if (is("--gif-every", kRender)) o.gif_every = static_cast<long>(a.count(opt, 1, 100000000));
    else if (is("--display", kRun)) display_value(a.value(opt), o);
    else if (is("--board", kRun)) o.board = a.value(opt);
    else if (is("--input", kRun)) o.input = input_value(opt, a.value(opt));
    else if (is("--record", kRun)) o.record = a.value(opt);
    else if (is("--screenshot", kRun)) o.screenshot = a.value(opt);
    else if (is("--attract", kRun)) o.attract = a.number(opt, 0, 1e7), o.attract_given = true;
    else if (is("--threads", kRun)) o.threads = static_cast<int>(a.count(opt, 1, 16));
    else if (is("--fps", kRun)) o.fps = a.number(opt, 1, 1000);
    else if (is("--stats", kRun)) o.stats = true;
    else return false;
    return true;
}

void parse_options(Args& a, Options& o, Command c) {
    while (a.more()) {
        const std::string opt = a.next();
        if (!parse_option(a, opt, o, c))
            usage_error("unknown option '" + opt + "' for " + command_name(c) + "; see 'noneuclid --help'.");
    }
}

void apply_settings(const Script& script, Options& o, Command c) {
    for (const Setting& s : script.settings) {
        const std::string where = script.file + ":" + std::to_string(s.line) + ": ";
        try {
            std::vector<std::string> words;
            if (s.key == "aa" || s.key == "hud") {  // flags: on or off
                words.push_back(std::string(parse_on_off(s.key, s.value) ? "--" : "--no-") + s.key);
            } else {
                words = {"--" + s.key, s.value};
            }
            Args args(words);
            const std::string opt = args.next();
            // A setting the command has no option for (the HUD for dump) does not matter to it.
            parse_option(args, opt, o, c);
        } catch (const UsageError& e) {
            usage_error(where + e.message);
        }
    }
}

void apply_board(const files::Board& b, Options& o) {
    o.scene = b.scene;
    if (!world::parse_engine(b.engine, o.engine)) o.engine = world::kDefaultEngine;  // the board file was checked when read
    o.projection = parse_projection("the board's projection", b.projection);
    o.aa = b.antialias;
    o.hud = b.hud;
    o.threads = b.threads;
    o.fps = b.fps;
    o.attract = b.idle_seconds;
    o.sweep = b.sweep_seconds;
    o.device = b.device;
}

Options layered_options(int argc, char** argv, int first, Command c, Script& script, const files::Board* board) {
    Options given = defaults(c);
    {
        Args args(argc, argv, first);
        parse_options(args, given, c);
    }
    if (!board && given.actions.empty()) return given;
    Options o = defaults(c);
    if (board) apply_board(*board, o);
    if (!given.actions.empty()) {
        ScriptError err;
        if (!load_script(given.actions, script, err)) usage_error(err.to_string() + ".");
        apply_settings(script, o, c);
    }
    Args args(argc, argv, first);
    parse_options(args, o, c);
    if (o.device.empty() && board) o.device = board->device;
    return o;
}

}  // namespace noneuclid::app
