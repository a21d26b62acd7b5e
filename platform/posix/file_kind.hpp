// A file's kind from its stat mode (app/platform.hpp's FileKind), for the files that write
// outputs (atomic_file.cpp) and keep tables (kept_file.cpp).
#pragma once

#include <sys/stat.h>

#include "app/platform.hpp"

namespace noneuclid::platform {

inline FileKind kind_of(mode_t mode) {
    if (S_ISREG(mode)) return FileKind::regular;
    if (S_ISDIR(mode)) return FileKind::directory;
    if (S_ISLNK(mode)) return FileKind::symlink;
    if (S_ISFIFO(mode)) return FileKind::fifo;
    if (S_ISCHR(mode) || S_ISBLK(mode)) return FileKind::device;
    if (S_ISSOCK(mode)) return FileKind::socket;
    return FileKind::other;
}

// What lstat finds at `path` (missing when nothing is there or it cannot be looked at; the
// caller's open says why), its stat in `st`.
inline FileKind kind_at(const char* path, struct stat& st) {
    if (lstat(path, &st) != 0) return FileKind::missing;
    return kind_of(st.st_mode);
}

}  // namespace noneuclid::platform
