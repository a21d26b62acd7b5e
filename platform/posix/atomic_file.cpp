// AtomicFile (app/platform.hpp): mkstemp beside the target, fsync, rename.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "app/platform.hpp"

namespace noneuclid::platform {

bool AtomicFile::open(const std::string& path, std::string& error) {
    abort();
    const std::filesystem::path p(path);
    if (p.filename().empty()) {
        error = "cannot write " + path + ": it names a directory, not a file: give a file name.";
        return false;
    }
    std::string temp = (p.parent_path() / ("." + p.filename().string() + ".XXXXXX")).string();
    const int fd = mkostemp(temp.data(), O_CLOEXEC);
    if (fd < 0) {
        error = "cannot write " + path + ": " + std::strerror(errno) + " (check the directory exists and is writable).";
        return false;
    }
    // mkstemp makes it 0600; give it what fopen would have (0666 less the umask).
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    file_ = fdopen(fd, "wb");
    if (!file_) {
        error = "cannot write " + path + ": " + std::strerror(errno) + ".";
        close(fd);
        unlink(temp.c_str());
        return false;
    }
    path_ = path, temp_ = temp;
    return true;
}

bool AtomicFile::commit(std::string& error) {
    if (!file_) {
        error = "cannot write " + path_ + ": it was not opened.";
        return false;
    }
    const bool written = std::fflush(file_) == 0 && !std::ferror(file_) && fsync(fileno(file_)) == 0;
    const int err = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!written || !closed || std::rename(temp_.c_str(), path_.c_str()) != 0) {
        error = "cannot write " + path_ + ": " + std::strerror(written && closed ? errno : err) +
                " (check the disk has room); it is left as it was.";
        unlink(temp_.c_str());
        return false;
    }
    // The rename itself reaches the disk with the directory.
    const std::string dir = std::filesystem::path(path_).parent_path().string();
    if (const int d = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); d >= 0) {
        fsync(d);
        close(d);
    }
    return true;
}

void AtomicFile::abort() {
    if (!file_) return;
    std::fclose(file_);
    file_ = nullptr;
    unlink(temp_.c_str());
}

}  // namespace noneuclid::platform
