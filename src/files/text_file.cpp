#include "files/text_file.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace noneuclid::files {

namespace {
// A limit: "64 KiB", "1 MiB".
std::string limit_text(std::uintmax_t bytes) {
    char buf[32];
    if (bytes >= (std::uintmax_t{1} << 20))
        std::snprintf(buf, sizeof buf, "%g MiB", static_cast<double>(bytes) / (1 << 20));
    else
        std::snprintf(buf, sizeof buf, "%g KiB", static_cast<double>(bytes) / 1024);
    return buf;
}
}  // namespace

bool read_text_file(const std::string& path, std::size_t limit, const char* what, std::string& out,
                    std::string& error) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);  // follows links: what would be read
    if (ec || !fs::exists(st)) {
        error = "cannot read it (" + (ec ? ec.message() : std::string("No such file or directory")) + ")";
        return false;
    }
    if (fs::is_directory(st)) {
        error = "it is a directory, not a file";
        return false;
    }
    if (!fs::is_regular_file(st)) {
        error = "it is not a regular file (a pipe, a socket or a device cannot be read as one)";
        return false;
    }
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > limit) {
        error = "it is " + std::to_string(size) + " bytes, over the " + limit_text(limit) + " " + what + " may have";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot read it (permission denied?)";
        return false;
    }
    out.assign(limit + 1, '\0');
    in.read(out.data(), static_cast<std::streamsize>(limit + 1));
    out.resize(static_cast<std::size_t>(in.gcount()));
    if (out.size() > limit) {  // it grew since it was measured
        error = "it is over the " + limit_text(limit) + " " + what + " may have";
        return false;
    }
    return true;
}

}  // namespace noneuclid::files
