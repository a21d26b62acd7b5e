// The options of every command: one struct, one table of options (app/options.cpp: each
// option's name, value, commands, help line and reader) from which the parser and each
// command's --help come. A recording's settings (app/script.hpp) are these options too: the
// world commands layer them as built-in defaults, then the board's (the kiosk), then the
// recording's, then the command line's, each over the last.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/args.hpp"
#include "fixed/accuracy.hpp"
#include "kinds/step.hpp"
#include "world/engines.hpp"
#include "app/script.hpp"
#include "geometry/measure.hpp"
#include "render/palette.hpp"
#include "files/board.hpp"
#include "world/scene.hpp"

namespace noneuclid::app {

// The commands (app/main.cpp's table has what each does).
enum class Command { run, render, dump, demo, accuracy, buttons, scores, scenes, measure, lesson };
inline constexpr int kCommandCount = 10;

// `noneuclid measure`: the instrument and its construction (docs/measure.md). Lengths in world
// units, angles in radians (degrees on the command line).
struct MeasureOptions {
    geo::Instrument instrument = geo::Instrument::triangle;
    std::vector<geo::Polar<double>> points;   // triangle: its three marks
    geo::Polar<double> centre{};              // circle
    double radius = 1;                        // circle
    double distance = 0.5, length = 1;        // parallels: d and s
    int sides = 3, around = 7;                // polygon: p and q
    double side = 1.2;                        // polygon: a
    double limit = 3.141592653589793;         // the limit circle's radius the marks must lie within
    bool table = false;                       // --format table: rounded, with units (else JSON)
};

struct Options {
    // The world (dump, render, run)
    std::string scene = "kiosk";
    bool has_curvature = false;
    double curvature = 0;
    std::optional<world::EngineKind> engine;  // none given: the kind of world's first (kinds/kinds.hpp)
    std::string actions;
    world::SceneParams params;
    long frames = 60;           // run: 0, until closed
    double dt = kinds::kStepSeconds;  // dump, render; run steps kStepSeconds a frame
    int width = 800, height = 480;
    geo::Projection projection = geo::Projection::azimuthal_equidistant;
    // The picture (render, run)
    render::PixelFormat format = render::PixelFormat::xrgb8888();
    bool aa = false;
    bool hud = false;           // run: true
    render::Palette palette = render::Palette::scene;  // the colours (docs/accessibility.md)
    bool large_hud = false;     // the HUD's text twice as large
    int hud_scale = 0;          // the HUD's pixels per font pixel; 0: 2 on a canvas 900 tall or more, else 1
    std::string caption;        // a lesson step's caption on the HUD (app/lesson.hpp; no option sets it)
    std::string title;          // a figure's label, top-left (app/figures.hpp; no option sets it)
    bool panels = true;         // the instruments' readings beside the disc (off: a worksheet's picture; no option)
    std::string lesson;         // run: play this lesson (a built-in's name or a file) instead of a scene
    std::string attract_lesson; // run: attract mode plays this lesson until a button is pressed
    bool one_button = false;    // run: fire alone plays (app/one_button.hpp)
    bool sound = false;         // run: the game's sound (docs/sound.md)
    std::string sound_device = "default";  // run: the ALSA device it plays on
    std::string language;       // the HUD's and lessons' language: en, de, fr; "" the locale's (resolve_language)
    std::string font;           // "" the default, "builtin", or a PSF file
    std::string legend;         // keys or buttons; "" the display's (render: buttons)
    long best = 0;              // the game's high score shown before any game ends (run: the table's)
    bool best_given = false;
    double line_width = 1;      // render
    long timelapse = 0;         // render
    long timelapse_grids = 0;   // render: and every this-many-th frame's grid (0: none)
    std::string out;            // render: the PNG
    std::string gif;            // render: the animated GIF
    long gif_every = 2;         // render: a GIF frame every this many frames
    // A live run
    std::string display;        // "" chosen, x11, fbdev, png
    std::string device;         // fbdev:DEVICE ("" the board's)
    std::string board, input = "auto", record, screenshot;
    std::string scores;         // the high-score table ("" the state directory's, "none")
    double attract = 0;         // idle seconds before attract mode; 0 off
    bool attract_given = false; // --attract (else the display's default)
    double sweep = 40;          // attract mode's sweep of K from -1 to +1, seconds (the board's)
    int threads = 1;
    double fps = 60;
    bool stats = false;
    bool size_given = false;    // --size or a recording's size (the window's, else the board's)
    // The other commands
    std::string out_dir = "out";   // demo
    fx::AccuracyOptions accuracy;  // accuracy: --samples, --random, --seed
    long events = 0;               // buttons: stop after this many (0: no limit)
    double timeout = 0;            // buttons: stop after this many seconds (0: none)
    MeasureOptions measure;        // measure
};

// The defaults of each command.
Options defaults(Command c);
// Reads one option `opt` (its value from `args`) into `o`; false if `c` has no such option.
bool parse_option(Args& args, const std::string& opt, Options& o, Command c);
// Reads every word of `args` as an option of `c` (a UsageError for one it has not, naming the
// commands that have it).
void parse_options(Args& args, Options& o, Command c);
// Command c's options as --help shows them: each one's name and value, its help line, and the
// choices it lists under it (engines, projections, ...).
struct OptionHelp {
    struct Choice {
        std::string name, help;
    };
    std::string head, help;
    std::vector<Choice> choices;
};
std::vector<OptionHelp> options_help(Command c);
// A recording's settings over `o`: a bad one is a UsageError naming the file and line.
void apply_settings(const Script& script, Options& o, Command c);
// The kiosk board's [display] defaults over `o`.
void apply_board(const files::Board& b, Options& o);

// The command line, with a recording's settings (and, for the kiosk, a board's) under it: the
// defaults, `board` if given, the settings of the --actions file if any (loaded into `script`),
// then the command line. A bad word or file is a UsageError.
Options layered_options(int argc, char** argv, int first, Command c, Script& script,
                        const files::Board* board = nullptr);

const char* command_name(Command c);
// The command named `name`; false if none is.
bool parse_command(const std::string& name, Command& out);
// The engine named `text`, or a UsageError naming `opt`.
world::EngineKind engine_value(const std::string& opt, const std::string& text);

}  // namespace noneuclid::app
