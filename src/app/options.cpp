#include "app/options.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstdint>
#include <iterator>
#include <vector>

#include "app/displays.hpp"
#include "lang/lang.hpp"
#include "world/earth.hpp"
#include "world/quote.hpp"

namespace noneuclid::app {

namespace {

constexpr unsigned bit(Command c) { return 1u << static_cast<unsigned>(c); }
constexpr unsigned kRun = bit(Command::run), kRender = bit(Command::render), kDump = bit(Command::dump),
                   kDemo = bit(Command::demo), kAccuracy = bit(Command::accuracy), kButtons = bit(Command::buttons),
                   kScores = bit(Command::scores), kMeasure = bit(Command::measure),
                   kLesson = bit(Command::lesson);
constexpr unsigned kWorld = kDump | kRender | kRun, kPicture = kRender | kRun;

using Choice = OptionHelp::Choice;
std::vector<Choice> engine_choices() {
    std::vector<Choice> out;
    for (std::size_t i = 0; i < world::kEngineCount; ++i)
        out.push_back({world::engine_name({i}), world::engine_help({i})});
    return out;
}
std::vector<Choice> projection_choices() {
    std::vector<Choice> out;
    for (geo::Projection p : geo::kProjections) out.push_back({geo::projection_name(p), geo::projection_help(p)});
    return out;
}
std::vector<Choice> format_choices() {
    std::vector<Choice> out;
    for (const render::PixelFormat& f : render::kNamedFormats)
        out.push_back({f.name, std::to_string(f.bits_per_pixel) + " bits a pixel"});
    return out;
}
std::vector<Choice> display_choices() {
    std::vector<Choice> out;
    std::size_t n = 0;
    const DisplayRow* rows = display_rows(n);
    for (std::size_t i = 0; i < n; ++i) out.push_back({rows[i].name, rows[i].help});
    return out;
}
std::vector<Choice> palette_choices() {
    std::vector<Choice> out;
    for (render::Palette p : render::kPalettes) out.push_back({render::palette_name(p), render::palette_help(p)});
    return out;
}
std::vector<std::string> names_of(const std::vector<Choice>& choices) {
    std::vector<std::string> names;
    for (const Choice& c : choices) names.push_back(c.name);
    return names;
}

// Points "r,θ r,θ ...": r a distance from O (0 or more), θ an angle in degrees.
std::vector<geo::Polar<double>> parse_points(const std::string& opt, const std::string& text) {
    std::vector<geo::Polar<double>> out;
    std::size_t at = 0;
    while (at < text.size()) {
        if (text[at] == ' ') {
            ++at;
            continue;
        }
        const std::size_t end = std::min(text.find(' ', at), text.size());
        const std::string word = text.substr(at, end - at);
        const std::size_t comma = word.find(',');
        const std::string sentence = opt + " needs points r,deg (a distance from O and an angle in degrees, e.g. 1,90), not '" + word + "'.";
        if (comma == std::string::npos) usage_error(sentence);
        char* stop = nullptr;
        const std::string rs = word.substr(0, comma), ts = word.substr(comma + 1);
        const double r = std::strtod(rs.c_str(), &stop);
        if (rs.empty() || *stop != '\0' || !(r >= 0 && r <= 1e4)) usage_error(sentence);
        const double t = std::strtod(ts.c_str(), &stop);
        if (ts.empty() || *stop != '\0' || !(t >= -1e6 && t <= 1e6)) usage_error(sentence);
        out.push_back({r, geo::wrap_pi(t * 3.141592653589793 / 180)});
        at = end;
    }
    if (out.empty()) usage_error(opt + " needs at least one point r,deg (e.g. 1,90).");
    return out;
}

std::string one_of(const std::string& opt, const std::string& text, const std::vector<std::string>& allowed) {
    for (const std::string& a : allowed)
        if (text == a) return text;
    usage_error(opt + " must be " + world::or_list(allowed) + ", not '" + text + "'.");
}
void display_value(const std::string& text, Options& o) {
    o.display = text, o.device.clear();
    if (text.rfind("fbdev:", 0) == 0) {
        o.display = "fbdev", o.device = text.substr(6);
        if (o.device.empty()) usage_error("--display fbdev: needs a device after the colon, e.g. fbdev:/dev/fb1.");
    }
    if (!display_named(o.display))
        usage_error("--display must be " + world::or_list(names_of(display_choices())) + " (or fbdev:/dev/fbN), not '" +
                    text + "'.");
}

// One option: its name, the word its value takes in --help ("" for a flag), the commands that
// take it, its help line, the choices --help lists under it (if any), and its reader.
struct OptionRow {
    const char* name;
    const char* value;
    unsigned commands;
    const char* help;
    std::vector<Choice> (*choices)();
    void (*read)(Args& a, const std::string& opt, Options& o, Command c);
};

void read_curvature(Args& a, const std::string& opt, Options& o, Command) {
    o.has_curvature = true, o.curvature = a.number(opt, -1, 1);
}

// The options, in the order --help lists them. (A reader's value checks are its sentences.)
const OptionRow kOptions[] = {
    {"--scene", "NAME|FILE", kWorld,
     "a built-in scene ('noneuclid scenes' lists them) or a TOML scene file (default kiosk; the kiosk: the board's)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { o.scene = a.value(opt); }},
    {"--curvature", "K", kWorld, "the curvature, -1 <= K <= 1: the world starts at it instead of the scene's", nullptr, read_curvature},
    {"--curvature", "K", kMeasure, "the curvature it measures at, -1 <= K <= 1 (default 0)", nullptr, read_curvature},
    {"--engine", "E", kWorld | kDemo, "the engine:", engine_choices,
     [](Args& a, const std::string& opt, Options& o, Command) { o.engine = engine_value(opt, a.value(opt)); }},
    {"--projection", "P", kWorld, "the view (P cycles them live):", projection_choices,
     [](Args& a, const std::string& opt, Options& o, Command) { o.projection = parse_projection(opt, a.value(opt)); }},
    {"--actions", "FILE", kWorld,
     "timed presses and releases, or a recording (run --record): its settings are defaults under the command line's",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { o.actions = a.value(opt); }},
    {"--frames", "N", kWorld, "steps after the first frame (default 60; run: until closed, its png display 600)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command c) {
         o.frames = static_cast<long>(a.count(opt, c == Command::run ? 1 : 0, 100000000));
     }},
    {"--size", "WxH", kWorld | kDemo, "canvas, window or picture size in pixels (default 800x480; demo: a panel's)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { parse_size(opt, a.value(opt), o.width, o.height), o.size_given = true; }},
    {"--dt", "S", kDump | kRender, "world seconds a step (default 1/60; run: always 1/60)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.dt = a.number(opt, 1e-4, 1); }},
    {"--bodies", "N", kWorld, "the stress scene's bodies (200)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.params.bodies = static_cast<int>(a.count(opt, 1, 100000)); }},
    {"--vertices", "N", kWorld, "the stress scene's vertices a body (8)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.params.vertices = static_cast<int>(a.count(opt, 1, 10000)); }},
    {"--tessellation", "N", kWorld, "the stress scene's points an edge (8)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.params.tessellation = static_cast<int>(a.count(opt, 1, 256)); }},
    // (One option, two meanings: a place on the Earth for the earth scene, a point of the world
    // for measure's circle.)
    {"--centre", "LAT,LON", kWorld, "the earth scene's centre, the place at O: LAT,LON in degrees (default 51.5,0: Greenwich)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) {
         const std::string v = a.value(opt);
         if (!world::parse_centre(v, o.params.centre_lat, o.params.centre_lon))
             usage_error(opt + " must be a latitude and a longitude in degrees, LAT,LON with -90 <= LAT <= 90 and -180 <= LON <= 180 (e.g. 51.5,0), not '" + v + "'.");
     }},
    {"--centre", "r,deg", kMeasure, "measure circle: its centre, a distance from O and an angle in degrees (default 0,0, O)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) {
         const std::vector<geo::Polar<double>> p = parse_points(opt, a.value(opt));
         if (p.size() != 1) usage_error(opt + " needs one point r,deg (e.g. 0.5,30).");
         o.measure.centre = p[0];
     }},
    {"--view", "KM", kWorld,
     "the earth scene zoomed by curvature: KM km from the centre to the screen's edge, at K = (KM / (pi 6371))^2 "
     "(default: the whole globe at K = 1)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) {
         o.params.view_km = a.number(opt, world::kEarthViewMinKm, world::kEarthViewMaxKm);
     }},
    {"--tissot", "", kWorld, "the earth scene with Tissot's indicatrices: circles of 500 km on a 30-degree grid, each "
     "drawn as the projection's ellipse there", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.params.tissot = true; }},
    {"--no-tissot", "", kWorld, "the earth scene without them (the default)", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.params.tissot = false; }},
    {"--aa", "", kPicture, "anti-aliased lines (default off; the kiosk: the board's)", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.aa = true; }},
    {"--no-aa", "", kPicture, "aliased lines", nullptr, [](Args&, const std::string&, Options& o, Command) { o.aa = false; }},
    {"--hud", "", kPicture, "K, the scene and the controls over the picture (run: on)", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.hud = true; }},
    {"--no-hud", "", kPicture | kDemo, "no HUD", nullptr, [](Args&, const std::string&, Options& o, Command) { o.hud = false; }},
    {"--palette", "P", kPicture, "the colours (docs/accessibility.md):", palette_choices,
     [](Args& a, const std::string& opt, Options& o, Command) {
         const std::string v = a.value(opt);
         if (!render::parse_palette(v, o.palette))
             throw UsageError{opt + " takes " + world::or_list(render::palette_names(), false) + ", not '" + world::printable(v) + "'."};
     }},
    {"--large-hud", "", kPicture, "the HUD's text twice as large (docs/accessibility.md)", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.large_hud = true; }},
    {"--no-large-hud", "", kPicture, "the HUD's text at its usual size (the default)", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.large_hud = false; }},
    {"--hud-scale", "N", kPicture,
     "the HUD's text size, N pixels per font pixel, 1 to 8 (default: 2 on a canvas 900 pixels tall or more, "
     "else 1; the web page sets it from the screen's pixel density)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { o.hud_scale = static_cast<int>(a.count(opt, 1, 8)); }},
    {"--lesson", "NAME|FILE", kRun, "play a lesson (docs/lessons.md) instead of one scene: as 'noneuclid lesson NAME'", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.lesson = a.value(opt); }},
    {"--attract-lesson", "NAME|FILE", kRun,
     "attract mode plays this lesson (docs/lessons.md) until a button is pressed, instead of flying the ship", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.attract_lesson = a.value(opt); }},
    {"--lang", "L", kPicture, "the language of the HUD, the lessons and the page: en, de or fr (default: the "
     "locale's, $LC_ALL, $LC_MESSAGES or $LANG, else en; docs/languages.md)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) {
         const std::string v = a.value(opt);
         lang::Language l{};
         if (!lang::parse_language(v, l))
             throw UsageError{opt + " takes " + lang::language_choices() + ", not '" + world::printable(v) + "'."};
         o.language = lang::language_code(l);
     }},
    {"--one-button", "", kRun, "fire alone plays: the ship turns by itself, hold fire to thrust, tap to fire (or, "
     "without the game, for the next K); docs/accessibility.md", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.one_button = true; }},
    {"--no-one-button", "", kRun, "every button does its own action (the default)", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.one_button = false; }},
    {"--sound", "", kRun, "the game's sound: fire, hit, crash, level, game over, thrust; N mutes it (default off; the kiosk: "
     "the board's; docs/sound.md)", nullptr, [](Args&, const std::string&, Options& o, Command) { o.sound = true; }},
    {"--no-sound", "", kRun, "no sound", nullptr, [](Args&, const std::string&, Options& o, Command) { o.sound = false; }},
    {"--sound-device", "NAME", kRun, "the ALSA device --sound plays on (default 'default'; 'aplay -L' lists them)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.sound_device = a.value(opt); }},
    {"--font", "F", kPicture,
     "the HUD's font: builtin or a PSF console font file (default $NONEUCLID_FONT, else Terminus or Fixed from "
     "/usr/share/consolefonts, else builtin)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { o.font = a.value(opt); }},
    {"--legend", "L", kPicture, "the HUD's controls line: keys or buttons (default: the display's)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.legend = one_of(opt, a.value(opt), {"keys", "buttons"}); }},
    {"--format", "F", kPicture, "the pixel format (render; run's png display):", format_choices,
     [](Args& a, const std::string& opt, Options& o, Command) { o.format = parse_format(opt, a.value(opt)); }},
    {"--best", "N", kPicture, "the game's high score to show (run: the table's; a recording's own)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) {
         o.best = static_cast<long>(a.count(opt, 0, 1000000000)), o.best_given = true;
     }},
    {"--out", "FILE.png", kRender, "where to write the last frame (--out or --gif is required)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.out = a.value(opt); }},
    {"--gif", "FILE.gif", kRender, "the run as an animated GIF, at the canvas size", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.gif = a.value(opt); }},
    {"--gif-every", "N", kRender, "a GIF frame every N frames (default 2: 30 a second)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.gif_every = static_cast<long>(a.count(opt, 1, 100000000)); }},
    {"--width", "PX", kRender, "line width in pixels (default 1)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.line_width = a.number(opt, 0.1, 64); }},
    {"--timelapse", "EVERY", kRender, "every EVERY-th frame's bodies over the earlier ones", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.timelapse = static_cast<long>(a.count(opt, 1, 100000000)); }},
    {"--timelapse-grids", "EVERY", kRender, "and every EVERY-th frame's grid, coloured by K", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) {
         o.timelapse_grids = static_cast<long>(a.count(opt, 1, 100000000));
     }},
    {"--display", "D", kRun, "where to show it (default: a window if DISPLAY is set, the kiosk on a console, else png):",
     display_choices, [](Args& a, const std::string& opt, Options& o, Command) { display_value(a.value(opt), o); }},
    {"--record", "FILE", kRun, "every control as it took effect, with the settings: render --actions FILE replays it", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.record = a.value(opt); }},
    {"--screenshot", "F", kRun, "at the end, what the display shows, as a PNG", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.screenshot = a.value(opt); }},
    {"--threads", "N", kRun, "draw on N threads (the same pixels; default 1, or the board's)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.threads = static_cast<int>(a.count(opt, 1, 16)); }},
    {"--attract", "SECONDS", kRun, "attract mode after this long without input (0: off, the default; the kiosk: the board's)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { o.attract = a.number(opt, 0, 1e7), o.attract_given = true; }},
    {"--fps", "CAP", kRun, "frame rate cap (default 60); world time is 1/60 s a frame whatever it is", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.fps = a.number(opt, 1, 1000); }},
    {"--stats", "", kRun, "at the end: frames, wall time, CPU; the frame rate on the HUD", nullptr,
     [](Args&, const std::string&, Options& o, Command) { o.stats = true; }},
    {"--board", "NAME|FILE", kRun | kButtons,
     "the kiosk's board: rpi-zero2w, rpi3, rpi4, rpi5, generic or a board file (default: from the device-tree model)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { o.board = a.value(opt); }},
    {"--input", "I", kRun | kButtons, "the kiosk's buttons: gpio, evdev, auto (the board's), none (run only)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command c) {
         o.input = one_of(opt, a.value(opt), c == Command::buttons ? std::vector<std::string>{"auto", "gpio", "evdev"}
                                                                   : std::vector<std::string>{"auto", "gpio", "evdev", "none"});
     }},
    {"--scores", "FILE", kRun | kScores,
     "the game's high-score table (default scores in $STATE_DIRECTORY, else $XDG_STATE_HOME/noneuclid, else "
     "~/.local/state/noneuclid; run: none keeps none)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { o.scores = a.value(opt); }},
    {"--out-dir", "DIR", kDemo, "where the pictures go (default out)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.out_dir = a.value(opt); }},
    {"--samples", "N", kAccuracy, "evenly spaced samples a row (262144)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.accuracy.dense = static_cast<long>(a.count(opt, 2, 100000000)); }},
    {"--random", "N", kAccuracy, "random samples a row (65536)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.accuracy.random = static_cast<long>(a.count(opt, 0, 100000000)); }},
    {"--seed", "S", kAccuracy, "the random samples' seed (20190101)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) {
         o.accuracy.seed = static_cast<unsigned long long>(a.count(opt, 0, INT64_MAX));
     }},
    {"--events", "N", kButtons, "stop after N presses and releases (default: no limit)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.events = static_cast<long>(a.count(opt, 1, 1000000000)); }},
    {"--points", "\"r,deg ...\"", kMeasure,
     "measure triangle: its three marks, each a distance from O and an angle in degrees (default \"1,90 1,210 1,330\")",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) { o.measure.points = parse_points(opt, a.value(opt)); }},
    {"--radius", "rho", kMeasure, "measure circle: its radius (default 1)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.measure.radius = a.number(opt, -1e6, 1e6); }},
    {"--distance", "d", kMeasure, "measure parallels: the common perpendicular's length (default 0.5)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.measure.distance = a.number(opt, -1e6, 1e6); }},
    {"--length", "s", kMeasure, "measure parallels: the arclength along each (default 1)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.measure.length = a.number(opt, -1e6, 1e6); }},
    {"--sides", "p", kMeasure, "measure polygon: each polygon's sides, 3 or more (default 3)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.measure.sides = static_cast<int>(a.count(opt, 3, 1000)); }},
    {"--around", "q", kMeasure, "measure polygon: polygons around the vertex, 3 or more (default 7)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.measure.around = static_cast<int>(a.count(opt, 3, 1000)); }},
    {"--side", "a", kMeasure, "measure polygon: the side's length (default 1.2)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.measure.side = a.number(opt, -1e6, 1e6); }},
    {"--format", "F", kMeasure,
     "json (the default: one object, every reading to 17 digits) or table (one row per reading, rounded, with its "
     "unit: degrees to 0.1, lengths in world units and areas in units squared to 0.001; docs/file-formats.md)",
     nullptr, [](Args& a, const std::string& opt, Options& o, Command) {
         o.measure.table = one_of(opt, a.value(opt), {"json", "table"}) == "table";
     }},
    {"--limit", "R", kMeasure, "the limit circle's radius: marks must lie within it (default pi)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.measure.limit = a.number(opt, 1e-3, 1e4); }},
    // (The lesson's own two, after its name; app/cmd_lesson.cpp reads them and hands the rest to run.)
    {"--worksheet", "FILE.png|FILE.pdf", kLesson,
     "the pupils' worksheet: each step's picture at the K its question asks about, its question and blanks for "
     "the readings (a PDF if FILE ends in .pdf, else a PNG of the pages)", nullptr,
     [](Args& a, const std::string& opt, Options&, Command) { a.value(opt); }},
    {"--answers", "FILE.png|FILE.pdf", kLesson, "the teacher's key: the same pages with the readings' values written in",
     nullptr, [](Args& a, const std::string& opt, Options&, Command) { a.value(opt); }},
    {"--paper", "a4|letter", kLesson, "the worksheet's paper (default a4)", nullptr,
     [](Args& a, const std::string& opt, Options&, Command) { one_of(opt, a.value(opt), {"a4", "letter"}); }},
    {"--print", "", kLesson, "a built-in lesson's file on standard output, to change and play as FILE", nullptr,
     [](Args&, const std::string&, Options&, Command) {}},
    {"--timeout", "SECONDS", kButtons, "stop after this long (default: never)", nullptr,
     [](Args& a, const std::string& opt, Options& o, Command) { o.timeout = a.number(opt, 0.001, 1e7); }},
};

// The row of option `name` for command c (an option may have a row for each command that reads
// it its own way), else its first row, else null.
const OptionRow* find_option(const std::string& name, Command c) {
    const OptionRow* first = nullptr;
    for (const OptionRow& r : kOptions) {
        if (name != r.name) continue;
        if (r.commands & bit(c)) return &r;
        if (!first) first = &r;
    }
    return first;
}

}  // namespace

world::EngineKind engine_value(const std::string& opt, const std::string& text) {
    world::EngineKind e;
    if (!world::parse_engine(text, e)) usage_error(opt + " must be " + world::or_list(world::engine_names()) + ", not '" + text + "'.");
    return e;
}

Options defaults(Command c) {
    Options o;
    if (c == Command::run) o.frames = 0, o.hud = true;
    if (c == Command::demo) o.hud = true;  // (and each figure's own size unless --size)
    return o;
}

bool parse_option(Args& a, const std::string& opt, Options& o, Command c) {
    const OptionRow* row = find_option(opt, c);
    if (!row || !(row->commands & bit(c))) return false;
    row->read(a, opt, o, c);
    return true;
}

void parse_options(Args& a, Options& o, Command c) {
    a.set_command(command_name(c));
    std::string previous;  // the option read last
    while (a.more()) {
        const std::string opt = a.next();
        if (a.last_attached())  // "--hud=on": a value given to an option that takes none
            usage_error("'" + previous + "' takes no value: write '" + previous + "' alone, not '" + previous + "=" + opt +
                        "'; see 'noneuclid " + command_name(c) + " --help'.");
        previous = opt;
        if (parse_option(a, opt, o, c)) continue;
        unsigned commands = 0;  // every command that has the option
        for (const OptionRow& r : kOptions)
            if (opt == r.name) commands |= r.commands;
        std::vector<std::string> others;
        for (int i = 0; i < kCommandCount; ++i)
            if (commands & (1u << i)) others.push_back(command_name(static_cast<Command>(i)));
        if (!others.empty())
            usage_error("'" + opt + "' is not an option of " + command_name(c) + " but of " + world::or_list(others) +
                        "; see 'noneuclid " + command_name(c) + " --help'.");
        usage_error("unknown option '" + opt + "' for " + command_name(c) + "; see 'noneuclid " + command_name(c) +
                    " --help'.");
    }
}

std::vector<OptionHelp> options_help(Command c) {
    std::vector<OptionHelp> out;
    for (const OptionRow& r : kOptions) {
        if (!(r.commands & bit(c))) continue;
        OptionHelp h{std::string(r.name) + (*r.value ? std::string(" ") + r.value : ""), r.help, {}};
        if (r.choices)
            for (const Choice& ch : r.choices()) h.choices.push_back({ch.name, ch.help});
        out.push_back(std::move(h));
    }
    return out;
}

void apply_settings(const Script& script, Options& o, Command c) {
    for (const Setting& s : script.settings) {
        const std::string where = script.file + ":" + std::to_string(s.line) + ": ";
        try {
            std::vector<std::string> words;
            if (s.key == "aa" || s.key == "hud" || s.key == "tissot" || s.key == "large-hud") {  // flags: on or off
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
    world::EngineKind engine;
    if (world::parse_engine(b.engine, engine)) o.engine = engine;  // (the board file was checked when read; "" names none)
    o.projection = parse_projection("the board's projection", b.projection);
    o.aa = b.antialias;
    o.hud = b.hud;
    o.large_hud = b.large_hud;
    o.one_button = b.one_button;
    o.sound = b.sound;
    if (!b.language.empty()) o.language = b.language;  // (checked when read)
    if (!render::parse_palette(b.palette, o.palette)) o.palette = render::Palette::scene;  // (checked when read)
    o.threads = b.threads;
    o.fps = b.fps;
    o.attract = b.idle_seconds;
    o.sweep = b.sweep_seconds;
    o.attract_lesson = b.attract_lesson;
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
