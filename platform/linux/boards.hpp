// Finding board files: by path, by name in the boards directories, or by the running
// machine's device-tree model (/proc/device-tree/model, "Raspberry Pi 4 Model B Rev 1.4").
#pragma once

#include <string>
#include <vector>

#include "app/platform.hpp"
#include "files/board.hpp"

namespace noneuclid::platform {

// Where board files are looked for, in order: $NONEUCLID_BOARDS, the installed
// <prefix>/share/noneuclid/boards, and the source tree's boards/ this binary was built from.
std::vector<std::string> board_dirs();

// The board override, read over the board `find_board` finds: $NONEUCLID_BOARD_OVERRIDE when
// set (empty: none), else <sysconfdir>/noneuclid/board.toml (/etc/noneuclid/board.toml for a
// /usr prefix, the Debian package's).
std::string board_override_path();

// `spec` is a file path (contains '/' or ends in .toml) or a board name (rpi4, generic, ...).
// On failure returns false with one sentence in `error`.
bool load_board(const std::string& spec, files::Board& out, std::string& error);

// The board file whose models match /proc/device-tree/model; "generic" when none does (or the
// machine has no device tree). `why` says which and because of what, for the start-up log.
bool detect_board(files::Board& out, std::string& why, std::string& error);

}  // namespace noneuclid::platform
