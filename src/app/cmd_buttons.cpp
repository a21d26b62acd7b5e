// `noneuclid buttons`: each press and release of the kiosk's buttons or keys, one line each
// (for checking the wiring).
#include <cstdio>

#include "app/args.hpp"
#include "app/commands.hpp"
#include "app/platform.hpp"

namespace noneuclid::app {

int buttons_command(int argc, char** argv, int first) {
    Options o = defaults(Command::buttons);
    Args args(argc, argv, first);
    parse_options(args, o, Command::buttons);
    files::Board board;
    std::string note, error;
    if (!platform::find_board(o.board, board, note, error)) usage_error(error + ".");
    std::fprintf(stderr, "noneuclid: %s.\n", note.c_str());
    return platform::print_buttons(board, o.input, o.events, o.timeout);
}

}  // namespace noneuclid::app
