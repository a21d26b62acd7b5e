// AtomicFile and output_allowed (app/platform.hpp). What is at the target decides: nothing or a
// regular file is replaced through a temporary file beside it (mkstemp, locked while it is
// written, fsync, rename, the directory fsync'd); a FIFO or the program's standard output is
// written into; anything else is refused, never replaced.
#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "app/platform.hpp"
#include "file_kind.hpp"

namespace noneuclid::platform {

namespace {

// A temporary file's name: "." + the target's name + kTempTag + six characters of mkstemp. The
// tag keeps a user's own hidden files (.NAME.backup) out of what the next write clears.
constexpr const char* kTempTag = ".noneuclid-";

enum class Plan { replace, stream, refuse };

// Whether `path`, through any links, is this process's standard output (/dev/stdout, /dev/fd/1,
// or the terminal or pipe it is).
bool is_standard_output(const std::string& path) {
    struct stat out{}, at{};
    return fstat(STDOUT_FILENO, &out) == 0 && stat(path.c_str(), &at) == 0 && out.st_dev == at.st_dev &&
           out.st_ino == at.st_ino;
}

bool names_fifo(const std::string& path) {
    struct stat at{};
    return stat(path.c_str(), &at) == 0 && S_ISFIFO(at.st_mode);
}

std::string refusal(const std::string& path, FileKind kind) {
    const char* fix = kind == FileKind::directory ? "give the path of a file in it"
                      : kind == FileKind::symlink ? "give the path of the file itself"
                                                  : "give the path of a file";
    return "cannot write " + path + ": it is " + file_kind_name(kind) + ", not a regular file, and is left alone: " +
           fix + ".";
}

// What open() does with `path`; `st` is what lstat found there (for a regular file, its mode).
Plan plan_for(const std::string& path, struct stat& st, FileKind& kind, std::string& error) {
    if (std::filesystem::path(path).filename().empty()) {
        error = "cannot write " + path + ": it names a directory, not a file: give a file name.";
        return Plan::refuse;
    }
    kind = kind_at(path.c_str(), st);
    if (kind == FileKind::missing || kind == FileKind::regular) return Plan::replace;
    if (is_standard_output(path)) return Plan::stream;
    if (kind == FileKind::fifo || (kind == FileKind::symlink && names_fifo(path))) return Plan::stream;
    error = refusal(path, kind);
    return Plan::refuse;
}

std::string directory_of(const std::string& path) {
    const std::string dir = std::filesystem::path(path).parent_path().string();
    return dir.empty() ? "." : dir;
}

// Whether `path` still names the file open as `fd`.
bool still_names(const std::string& path, int fd) {
    struct stat a{}, b{};
    return fstat(fd, &a) == 0 && lstat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// Removes the temporary files of earlier writes of `name` whose writer is gone (killed, or a
// power cut): ours, regular, and not locked. A live writer holds its lock from the moment it
// checks its own name (create_temp), so its file is never taken.
void clear_leftovers(const std::string& dir, const std::string& name) {
    const std::string prefix = "." + name + kTempTag;
    DIR* d = opendir(dir.c_str());
    if (!d) return;
    while (const dirent* e = readdir(d)) {
        const std::string n = e->d_name;
        if (n.size() != prefix.size() + 6 || n.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string full = dir + "/" + n;
        const int fd = ::open(full.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (fd < 0) continue;
        struct stat st{};
        if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_uid == geteuid() && flock(fd, LOCK_EX | LOCK_NB) == 0 &&
            still_names(full, fd))
            unlink(full.c_str());
        close(fd);
    }
    closedir(d);
}

// A new temporary file beside the target, locked; -1 with errno set.
int create_temp(const std::string& dir, const std::string& name, std::string& temp) {
    for (int attempt = 0; attempt < 8; ++attempt) {
        temp = dir + "/." + name + kTempTag + "XXXXXX";
        const int fd = mkostemp(temp.data(), O_CLOEXEC);
        if (fd < 0) return -1;
        // Another write's clear_leftovers may have taken it in the instant before the lock: then
        // its name is gone (or about to be), and a new one is made.
        if (flock(fd, LOCK_EX | LOCK_NB) == 0 && still_names(temp, fd)) return fd;
        close(fd);
    }
    errno = EBUSY;
    return -1;
}

// The mode a new file gets (0666 less the umask), or a replaced file's own; as root, its owner.
void give_mode(int fd, FileKind kind, const struct stat& st) {
    if (kind != FileKind::regular) {
        const mode_t mask = umask(0);
        umask(mask);
        fchmod(fd, 0666 & ~mask);
        return;
    }
    // The group as well where this user may give it; the owner only as root. Failing either
    // leaves ours: the permissions below still hold.
    if (fchown(fd, geteuid() == 0 ? st.st_uid : static_cast<uid_t>(-1), st.st_gid) != 0) errno = 0;
    fchmod(fd, st.st_mode & 0777);
}

// A FIFO (or standard output) to write into: opened without waiting for a reader.
int open_stream(const std::string& path, std::string& error) {
    if (is_standard_output(path)) return fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    struct stat st{};
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISFIFO(st.st_mode)) {
        error = "cannot write " + path + ": " +
                (fd < 0 && errno == ENXIO ? std::string("it is a pipe (FIFO) that nothing reads: start its reader first.")
                                          : std::string("it is no longer a pipe (FIFO) to write into: check the path."));
        if (fd >= 0) close(fd);
        return -1;
    }
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // a slow reader is waited for
    return fd;
}

}  // namespace

bool output_allowed(const std::string& path, std::string& error) {
    struct stat st{};
    FileKind kind = FileKind::missing;
    return plan_for(path, st, kind, error) != Plan::refuse;
}

bool AtomicFile::open(const std::string& path, std::string& error) {
    abort();
    struct stat st{};
    FileKind kind = FileKind::missing;
    const Plan plan = plan_for(path, st, kind, error);
    if (plan == Plan::refuse) return false;
    int fd = -1;
    std::string temp;
    if (plan == Plan::stream) {
        if ((fd = open_stream(path, error)) < 0) {
            if (error.empty()) error = "cannot write " + path + ": " + std::strerror(errno) + ".";
            return false;
        }
    } else {
        const std::string dir = directory_of(path), name = std::filesystem::path(path).filename().string();
        clear_leftovers(dir, name);
        if ((fd = create_temp(dir, name, temp)) < 0) {
            error = "cannot write " + path + ": " + std::strerror(errno) + " (check the directory exists and is writable).";
            return false;
        }
        give_mode(fd, kind, st);
    }
    file_ = fdopen(fd, "wb");
    if (!file_) {
        error = "cannot write " + path + ": " + std::strerror(errno) + ".";
        if (!temp.empty()) unlink(temp.c_str());
        close(fd);
        return false;
    }
    path_ = path, temp_ = temp, stream_ = plan == Plan::stream;
    return true;
}

bool AtomicFile::commit(std::string& error) {
    if (!file_) {
        error = "cannot write " + path_ + ": it was not opened.";
        return false;
    }
    if (stream_) {
        const bool written = std::fflush(file_) == 0 && !std::ferror(file_);
        const int err = errno;
        const bool closed = std::fclose(file_) == 0;
        file_ = nullptr;
        if (written && closed) return true;
        error = "cannot write " + path_ + ": " + std::strerror(written ? errno : err) + "; what was written is cut short.";
        return false;
    }
    // Renamed while the temporary file is still open and locked: no other write clears it first.
    bool written = std::fflush(file_) == 0 && !std::ferror(file_) && fsync(fileno(file_)) == 0;
    int err = errno;
    struct stat st{};
    const FileKind now = kind_at(path_.c_str(), st);
    if (written && now != FileKind::missing && now != FileKind::regular) {
        error = refusal(path_, now);
        abort();
        return false;
    }
    if (written && std::rename(temp_.c_str(), path_.c_str()) != 0) written = false, err = errno;
    if (!written) {
        error = "cannot write " + path_ + ": " + std::strerror(err) + " (check the disk has room); it is left as it was.";
        abort();
        return false;
    }
    std::fclose(file_);  // (its data is on the disk: fsync said so)
    file_ = nullptr;
    // The rename itself reaches the disk with the directory.
    if (const int d = ::open(directory_of(path_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); d >= 0) {
        fsync(d);
        close(d);
    }
    return true;
}

void AtomicFile::abort() {
    if (!file_) return;
    if (!stream_) unlink(temp_.c_str());  // before the close, while it is still locked
    std::fclose(file_);
    file_ = nullptr;
}

}  // namespace noneuclid::platform
