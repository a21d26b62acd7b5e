// What a path holds, in words (app/platform.hpp's FileKind), for the sentences that refuse it.

#include "app/platform.hpp"

namespace noneuclid::platform {

const char* file_kind_name(FileKind kind) {
    switch (kind) {
        case FileKind::missing: return "nothing (there is no such file)";
        case FileKind::regular: return "a regular file";
        case FileKind::directory: return "a directory";
        case FileKind::symlink: return "a symbolic link";
        case FileKind::fifo: return "a pipe (FIFO)";
        case FileKind::device: return "a device";
        case FileKind::socket: return "a socket";
        case FileKind::other: break;
    }
    return "neither a file nor a directory";
}

}  // namespace noneuclid::platform
