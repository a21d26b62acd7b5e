// `noneuclid buttons`: each press and release of the kiosk's buttons or keys, one line each
// (for checking the wiring).
#include <cstdio>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "app/platform.hpp"

namespace noneuclid::app {

int buttons_command(int argc, char** argv, int first) {
    std::string board_spec, input = "auto";
    long events = 0;
    double timeout = 0;
    Args args(argc, argv, first);
    while (args.more()) {
        const std::string opt = args.next();
        if (opt == "--board") board_spec = args.value(opt);
        else if (opt == "--input") {
            input = args.value(opt);
            if (input != "auto" && input != "gpio" && input != "evdev")
                usage_error("--input must be auto, gpio or evdev for buttons, not '" + input + "'.");
        } else if (opt == "--events") events = static_cast<long>(args.count(opt, 1, 1000000000));
        else if (opt == "--timeout") timeout = args.number(opt, 0.001, 1e7);
        else usage_error("unknown option '" + opt + "' for buttons; see 'noneuclid --help'.");
    }
    files::Board board;
    std::string note, error;
    if (!platform::find_board(board_spec, board, note, error)) usage_error(error + ".");
    std::fprintf(stderr, "noneuclid: %s.\n", note.c_str());
    return platform::print_buttons(board, input, events, timeout);
}

}  // namespace noneuclid::app
