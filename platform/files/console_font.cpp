#include "files/console_font.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <system_error>
#include <utility>

namespace noneuclid::platform {

namespace {

// Console fonts are a few KiB (the largest Terminus, 32x16 with 512 glyphs, is 32 KiB).
constexpr std::size_t kMaxFontBytes = std::size_t{16} << 20;

constexpr const char* kPreferred[] = {
    "Lat15-Terminus16.psf.gz",
    "Uni2-Terminus16.psf.gz",
    "Lat15-Fixed16.psf.gz",
    "Uni2-Fixed16.psf.gz",
};

// zlib's messages start with "<path>: "; the caller names the path itself.
std::string gz_reason(gzFile file, const std::string& path) {
    int errnum = Z_OK;
    const char* message = gzerror(file, &errnum);
    if (errnum == Z_ERRNO)
        return std::strerror(errno);
    std::string_view m = message ? message : "unknown zlib error";
    const std::string prefix = path + ": ";
    if (m.substr(0, prefix.size()) == prefix)
        m.remove_prefix(prefix.size());
    return std::string(m);
}

std::string describe(const LoadedFont& f) {
    return f.source + " (" + std::to_string(f.font.width) + "x" + std::to_string(f.font.height)
           + ")";
}

// What a path that is not a regular file is, for the sentence that refuses it.
const char* not_a_file(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory, not a file";
    if (S_ISFIFO(mode)) return "a pipe (FIFO), not a file (it is not waited on)";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device, not a file";
    return "not a regular file";
}

bool ends_with(std::string_view s, std::string_view suffix) {
    return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

}  // namespace

bool load_console_font(const std::string& path, LoadedFont& out, std::string& error) {
    // Only a regular file is read: opened without waiting (a FIFO would block until something
    // wrote to it), then checked for what it is before a byte is read.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    struct stat st {};
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        const int e = errno;
        error = path + (fd < 0 ? ": cannot open the font file (" + std::string(std::strerror(e)) + ")"
                               : std::string(": the font file is ") + not_a_file(st.st_mode));
        if (fd >= 0) close(fd);
        return false;
    }
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    errno = 0;
    gzFile file = gzdopen(fd, "rb");
    if (file == nullptr) {
        const int e = errno;
        close(fd);
        error = path + ": cannot open the font file ("
                + (e != 0 ? std::strerror(e) : "out of memory") + ")";
        return false;
    }
    std::vector<uint8_t> bytes;
    std::string reason;
    for (;;) {
        const std::size_t at = bytes.size();
        bytes.resize(at + 65536);
        const int n = gzread(file, bytes.data() + at, 65536);
        if (n < 0) {
            reason = "cannot read the font file (" + gz_reason(file, path) + ")";
            break;
        }
        bytes.resize(at + std::size_t(n));
        if (n == 0) {
            int errnum = Z_OK;
            gzerror(file, &errnum);
            if (errnum != Z_OK)
                reason = "cannot read the font file (" + gz_reason(file, path) + ")";
            break;
        }
        if (bytes.size() > kMaxFontBytes) {
            reason = "the font file is larger than 16 MiB, far too large for a console font";
            break;
        }
    }
    const int closed = gzclose(file);
    if (reason.empty() && closed == Z_BUF_ERROR)
        reason = "cannot read the font file (the compressed data is truncated)";
    if (!reason.empty()) {
        error = path + ": " + reason;
        return false;
    }

    render::Font font;
    std::string why;
    if (!render::parse_psf(bytes.data(), bytes.size(), font, why)) {
        error = path + ": " + why;
        return false;
    }
    // font.glyphs points into `bytes`; re-point it into out.bytes after the move.
    const std::ptrdiff_t offset = font.glyphs - bytes.data();
    out.bytes = std::move(bytes);
    font.glyphs = out.bytes.data() + offset;
    out.font = font;
    out.source = path;
    return true;
}

LoadedFont default_hud_font(std::string* note, const std::string& console_fonts_dir) {
    const auto say = [note](std::string sentence) {
        if (note)
            *note = std::move(sentence);
    };
    LoadedFont font;
    std::string error;
    std::string env_failure;  // appended to the note when $NONEUCLID_FONT was set but unusable
    if (const char* env = std::getenv("NONEUCLID_FONT"); env != nullptr && *env != '\0') {
        if (load_console_font(env, font, error)) {
            say("HUD font: " + describe(font) + ", chosen by NONEUCLID_FONT.");
            return font;
        }
        env_failure = ", since NONEUCLID_FONT is unusable (" + error + ")";
    }

    const std::filesystem::path dir(console_fonts_dir);
    for (const char* name : kPreferred) {
        if (load_console_font((dir / name).string(), font, error)) {
            say("HUD font: " + describe(font) + ", the preferred console font" + env_failure + ".");
            return font;
        }
    }

    std::vector<std::string> others;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const bool preferred = std::find_if(std::begin(kPreferred), std::end(kPreferred),
                                            [&name](const char* p) { return name == p; })
                               != std::end(kPreferred);
        if (!preferred && (ends_with(name, ".psf.gz") || ends_with(name, ".psfu.gz")))
            others.push_back(it->path().string());
    }
    std::sort(others.begin(), others.end());
    for (const std::string& path : others) {
        if (load_console_font(path, font, error)) {
            say("HUD font: " + describe(font) + ", the first usable font in " + console_fonts_dir
                + " (none of the preferred Terminus or Fixed 16-pixel fonts is there)" + env_failure
                + ".");
            return font;
        }
    }

    font = LoadedFont{};
    font.font = render::builtin_font();
    font.source = "built-in 6x8";
    say("HUD font: the built-in 6x8 font, as no usable console font is in " + console_fonts_dir
        + " (Debian's console-setup-linux provides them)" + env_failure + ".");
    return font;
}

bool hud_font(const std::string& choice, LoadedFont& out, std::string& error) {
    if (choice.empty()) {
        out = default_hud_font(nullptr);
        return true;
    }
    if (choice == "builtin") {
        out = LoadedFont{};
        out.font = render::builtin_font();
        out.source = "built-in 6x8";
        return true;
    }
    if (load_console_font(choice, out, error)) return true;
    error += ": give --font a PSF console font (gzip-compressed or not), or builtin.";
    return false;
}

}  // namespace noneuclid::platform
