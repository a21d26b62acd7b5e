#include "app/commands.hpp"

namespace noneuclid::app {

// In Command's order.
const CommandRow kCommands[kCommandCount] = {
    {Command::run, "run",
     "a scene live: an X11 window when DISPLAY is set, the framebuffer and the board's buttons on a console (the "
     "kiosk), else the headless display that writes its last frame as a PNG; what options without a command do",
     "[OPTIONS]", run_command},
    {Command::render, "render", "run a scene and write its last frame as a PNG, or the whole run as an animated GIF",
     "[OPTIONS]", render_command},
    {Command::dump, "dump", "run a scene and write its state as JSON Lines, one line a frame", "[OPTIONS]", dump_command},
    {Command::demo, "demo",
     "the kiosk's picture and the paper's figures as PNG files in ./out; what the program does when given nothing",
     "[OPTIONS]", demo_command},
    {Command::accuracy, "accuracy",
     "every fixed-point function against std:: double and the engines at the screen, as tables; exit status 1 if a "
     "row misses its bound",
     "[OPTIONS]", accuracy_command},
    {Command::buttons, "buttons", "print each press and release of the kiosk's buttons (a wiring check)", "[OPTIONS]", buttons_command},
    {Command::scores, "scores", "print the game's high-score table", "[OPTIONS]", scores_command},
    {Command::scenes, "scenes", "list the built-in scenes, one line each", "[OPTIONS]", scenes_command},
    {Command::measure, "measure",
     "an instrument's readings at one curvature as one JSON object: triangle (angles, excess, area), circle "
     "(circumference and area against the flat ones), parallels (how far apart), polygon (the gap, the closing K)",
     "triangle|circle|parallels|polygon [OPTIONS]", measure_command},
    {Command::lesson, "lesson",
     "the lessons listed; a lesson (built-in or a file) played step by step on run's display with run's options, "
     "or --worksheet FILE and --answers FILE: its worksheet and the key (PNG or PDF); --print: a built-in lesson's file",
     "[NAME|FILE [--worksheet FILE] [--answers FILE] [--paper a4|letter] | --print] [run's OPTIONS]]", lesson_command},
};

const char* command_name(Command c) { return kCommands[static_cast<int>(c)].name; }

bool parse_command(const std::string& name, Command& out) {
    for (const CommandRow& r : kCommands)
        if (name == r.name) return out = r.command, true;
    return false;
}

}  // namespace noneuclid::app
