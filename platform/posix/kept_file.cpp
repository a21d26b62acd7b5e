// Files the program keeps and shares (app/platform.hpp): read without following a link or
// opening anything but a regular file, set aside under a name no earlier one has, and a lock on
// their directory across read, change and write.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>

#include "app/platform.hpp"
#include "file_kind.hpp"

namespace noneuclid::platform {

namespace {
constexpr int kLockNaps = 100;  // of 50 ms: five seconds
}

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

bool read_kept_file(const std::string& path, std::size_t limit, std::string& out, FileKind& kind, std::string& error) {
    out.clear();
    struct stat st{};
    errno = 0;
    kind = kind_at(path.c_str(), st);
    if (kind == FileKind::missing && errno == ENOENT) return true;
    if (kind == FileKind::missing) {
        error = std::string("cannot look at it (") + std::strerror(errno) + ")";
        return false;
    }
    if (kind != FileKind::regular) {
        error = std::string("it is ") + file_kind_name(kind) + ", not a regular file";
        return false;
    }
    // Opened as what lstat saw: a link put there since is not followed, a FIFO not waited on.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        error = fd < 0 ? std::string("cannot read it (") + std::strerror(errno) + ")" : "it is no longer a regular file";
        if (fd >= 0) close(fd);
        return false;
    }
    out.resize(limit + 1);
    std::size_t got = 0;
    while (got < out.size()) {
        const ssize_t n = read(fd, out.data() + got, out.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = std::string("cannot read it (") + std::strerror(errno) + ")";
            close(fd);
            out.clear();
            return false;
        }
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    close(fd);
    out.resize(got);
    return true;
}

bool set_aside(const std::string& path, const std::string& suffix, std::string& aside, std::string& error) {
    struct stat st{};
    if (kind_at(path.c_str(), st) != FileKind::regular) {
        error = "it is no longer a regular file";
        return false;
    }
    for (int n = 1; n <= 99; ++n) {
        aside = path + suffix + (n == 1 ? std::string() : "." + std::to_string(n));
        if (renameat2(AT_FDCWD, path.c_str(), AT_FDCWD, aside.c_str(), RENAME_NOREPLACE) == 0) return true;
        if (errno == EEXIST) continue;
        // A file system without RENAME_NOREPLACE: a second name, then the first one removed.
        if (errno == EINVAL || errno == ENOSYS) {
            if (link(path.c_str(), aside.c_str()) == 0) {
                unlink(path.c_str());
                return true;
            }
            if (errno == EEXIST) continue;
        }
        error = std::string("it could not be set aside (") + std::strerror(errno) + ")";
        return false;
    }
    error = "it could not be set aside: " + path + suffix + " and 98 more are there already (remove them)";
    return false;
}

DirectoryLock::DirectoryLock(const std::string& path) {
    std::string dir = std::filesystem::path(path).parent_path().string();
    if (dir.empty()) dir = ".";
    fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd_ < 0) return;
    // Its holders are quick (a read and a write of a small file): waited for in short naps, so
    // that a process holding it for ever (not one of ours) costs a bounded wait, not a hang.
    for (int nap = 0; nap <= kLockNaps; ++nap) {
        if (flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
        if (errno != EWOULDBLOCK && errno != EINTR) break;
        const timespec pause{0, 50'000'000};
        nanosleep(&pause, nullptr);
    }
    busy_ = errno == EWOULDBLOCK || errno == EINTR;
    close(fd_);
    fd_ = -1;
}

DirectoryLock::~DirectoryLock() {
    if (fd_ >= 0) close(fd_);
}

}  // namespace noneuclid::platform
