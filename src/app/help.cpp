// `noneuclid --help`, each command's --help, `noneuclid scenes` and the version: generated from
// the tables of commands (app/commands.cpp), options (app/options.cpp) and scenes
// (world/scenes.cpp), so that help and code cannot disagree.
#include <algorithm>
#include <cstdio>
#include <string>

#include "app/commands.hpp"
#include "world/scene.hpp"

namespace noneuclid::app {

namespace {
// `text` after `indent` columns, wrapped at 100.
std::string wrapped(const std::string& text, std::size_t indent) {
    std::string out, line;
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.find(' ', at);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(at, end - at);
        if (!line.empty() && indent + line.size() + 1 + word.size() > 100) {
            out += line + "\n" + std::string(indent, ' ');
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
        at = end + 1;
    }
    return out + line;
}
}  // namespace

const char* version() { return NONEUCLID_VERSION; }

void print_help() {
    std::string out =
        "Usage: noneuclid [COMMAND] [OPTIONS]\n"
        "\n"
        "A 2D engine for spaces of constant curvature K in [-1, 1], after Osudin, Child & He\n"
        "(2019): bodies fly through a spherical, flat or hyperbolic world while K changes.\n"
        "\n"
        "commands:\n";
    for (const CommandRow& c : kCommands) {
        std::string head = std::string("  ") + c.name;
        head.resize(12, ' ');
        out += head + wrapped(c.summary, 12) + "\n";
    }
    out +=
        "\n"
        "'noneuclid COMMAND --help' lists a command's options; options with no command are run's\n"
        "(noneuclid --scene asteroids plays the game).\n"
        "\n"
        "keys (run on a desktop): arrows or WASD fly, Space (or Ctrl) fires, + and - change K,\n"
        "1 2 3 set K to -1, 0, +1, P the next projection, H the HUD, R reset, Esc quits.\n"
        "\n"
        "  -h, --help          this help\n"
        "  --version           the version\n";
    std::fputs(out.c_str(), stdout);
}

void print_command_help(Command c) {
    const CommandRow& row = kCommands[static_cast<int>(c)];
    std::string out = std::string("Usage: noneuclid ") + row.name + " " + row.usage + "\n\n" + wrapped(row.summary, 0) + ".\n";
    const std::vector<OptionHelp> options = options_help(c);
    out += options.empty() ? "\nIt takes no options.\n" : "\noptions:\n";
    const bool runs = c == Command::lesson;  // (and after them, run's: the display, --lang, --size, ...)
    auto column = [](std::string head, std::size_t width) {
        head.resize(std::max(head.size() + 1, width), ' ');
        return head;
    };
    for (const OptionHelp& h : options) {
        const std::string head = column("  " + h.head, 24);
        out += head + wrapped(h.help, head.size()) + "\n";
        for (const OptionHelp::Choice& ch : h.choices) {
            const std::string name = column("      " + ch.name, 24);
            out += name + wrapped(ch.help, name.size()) + "\n";
        }
    }
    if (runs) out += "\n" + wrapped("and, for the lesson played, run's options ('noneuclid run --help'): the display, --lang, --size and the rest.", 0) + "\n";
    std::fputs(out.c_str(), stdout);
}

int scenes_command(int argc, char** argv, int first) {
    Options o = defaults(Command::scenes);
    Args args(argc, argv, first);
    parse_options(args, o, Command::scenes);
    std::size_t width = 0;
    for (const world::SceneInfo& s : world::builtin_scenes()) width = std::max(width, std::string(s.name).size());
    for (const world::SceneInfo& s : world::builtin_scenes())
        std::printf("%-*s  %s\n", static_cast<int>(width), s.name, s.about);
    return 0;
}

}  // namespace noneuclid::app
