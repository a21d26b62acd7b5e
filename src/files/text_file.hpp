// Reading an input file (a scene, a board, an actions file) whole, guarded: only a regular file,
// checked before it is opened (so a FIFO cannot block the program and a directory or a device
// such as /dev/zero is not read at all), and at most `limit` bytes. Standard C++ only.
#pragma once

#include <cstddef>
#include <string>

namespace noneuclid::files {

// The size limits of the inputs (docs/reliability.md).
inline constexpr std::size_t kSceneFileLimit = std::size_t{1} << 20;    // 1 MiB
inline constexpr std::size_t kBoardFileLimit = std::size_t{64} << 10;   // 64 KiB
inline constexpr std::size_t kActionsFileLimit = std::size_t{16} << 20; // 16 MiB: months of a kiosk's presses

// The file's bytes in `out`; false with one sentence (without the path, which the caller
// names, and without a full stop) in `error`: "cannot read it (No such file or directory)",
// "it is a directory, not a file", "it is 3.2 MiB, over the 1 MiB a scene file may have"...
// `what` names the kind of file for the last one ("a scene file").
bool read_text_file(const std::string& path, std::size_t limit, const char* what, std::string& out,
                    std::string& error);

}  // namespace noneuclid::files
