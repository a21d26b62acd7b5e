// write_png, read_png and read_texture (app/platform.hpp) with libpng.
#include "app/platform.hpp"

#include <png.h>
#include <sys/stat.h>
#include <zlib.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include "files/text_file.hpp"

namespace noneuclid::platform {

namespace {
// libpng's errors and warnings go into our sentence, not to stderr on their own line.
struct PngMessages {
    std::string text;
};
[[noreturn]] void png_failed(png_structp png, png_const_charp message) {
    if (auto* m = static_cast<PngMessages*>(png_get_error_ptr(png))) m->text = message ? message : "";
    png_longjmp(png, 1);
}
void png_warned(png_structp, png_const_charp) {}

// Every libpng call that can fail sits in one of the three *_guarded functions: each holds its
// own setjmp, returns when libpng longjmps to it, and builds no std::string (GCC's -Wclobbered
// flags libstdc++'s string internals inlined into a function that calls setjmp); the callers
// make the sentences.
enum class Png { done, failed, stopped };

// The canvas's rows, top to bottom; stopped if a stop signal came first.
Png encode_guarded(png_structp png, png_infop info, std::FILE* file, const render::Canvas& canvas, png_byte* row) {
    if (setjmp(png_jmpbuf(png))) return Png::failed;
    png_init_io(png, file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(canvas.width()), static_cast<png_uint_32>(canvas.height()), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < canvas.height(); ++y) {
        for (int x = 0; x < canvas.width(); ++x) {
            const render::Rgb c = canvas.get(x, y);
            row[static_cast<std::size_t>(x) * 3] = c.r;
            row[static_cast<std::size_t>(x) * 3 + 1] = c.g;
            row[static_cast<std::size_t>(x) * 3 + 2] = c.b;
        }
        png_write_row(png, row);
        if (stop_signal() != 0) return Png::stopped;
    }
    png_write_end(png, nullptr);
    return Png::done;
}

// The header, with every image converted to 8-bit RGB rows: their width and height.
Png read_header_guarded(png_structp png, png_infop info, std::size_t& width, std::size_t& height) {
    if (setjmp(png_jmpbuf(png))) return Png::failed;
    png_read_info(png, info);
    png_set_expand(png);  // palette and grey below 8 bits to 8-bit RGB or grey
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    if (png_get_rowbytes(png, info) != width * 3) png_error(png, "not 8-bit RGB after conversion");
    return Png::done;
}

// The rows, into the caller's memory.
Png read_rows_guarded(png_structp png, png_bytep* rows) {
    if (setjmp(png_jmpbuf(png))) return Png::failed;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return Png::done;
}

// The header and the rows into rgb (width x height x 3 bytes); false if libpng failed.
template <class Buffer>
bool read_guarded(png_structp png, png_infop info, std::size_t& width, std::size_t& height, Buffer& rgb) {
    if (read_header_guarded(png, info, width, height) != Png::done) return false;
    rgb.assign(width * height * 3, 0);
    std::vector<png_bytep> rows(height);
    for (std::size_t y = 0; y < height; ++y) rows[y] = reinterpret_cast<png_bytep>(&rgb[y * width * 3]);
    return read_rows_guarded(png, rows.data()) == Png::done;
}
}  // namespace

bool write_png(const std::string& path, const render::Canvas& canvas, std::string& error) {
    AtomicFile out;
    if (!out.open(path, error)) return false;
    PngMessages messages;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &messages, png_failed, png_warned);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        error = "cannot write " + path + ": libpng could not start (out of memory?).";
        return false;
    }
    std::vector<png_byte> row(static_cast<std::size_t>(canvas.width()) * 3);
    const Png result = encode_guarded(png, info, out.file(), canvas, row.data());
    const int err = errno;
    png_destroy_write_struct(&png, &info);
    if (result == Png::failed) {
        error = "cannot write " + path + ": " +
                (std::ferror(out.file()) ? std::string(std::strerror(err)) + " (check the disk has room)"
                                         : "libpng: " + messages.text) +
                "; it is left as it was.";
        return false;  // out's destructor removes the temporary file
    }
    if (result == Png::stopped) {
        error = "stopped by signal " + std::to_string(stop_signal()) + " while writing " + path +
                "; it is left as it was.";
        return false;
    }
    return out.commit(error);
}

bool read_png(const std::string& path, int& width, int& height, std::string& rgb, std::string& error) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        error = "cannot read " + path + ": " + std::strerror(errno);
        return false;
    }
    PngMessages messages;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &messages, png_failed, png_warned);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    std::size_t w = 0, h = 0;
    bool read = false;
    if (png && info) {
        png_init_io(png, f);
        read = read_guarded(png, info, w, h, rgb);
    }
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(f);
    if (!read) {
        error = "cannot read " + path + ": not a PNG file libpng can read" +
                (messages.text.empty() ? std::string() : " (" + messages.text + ")");
        return false;
    }
    width = static_cast<int>(w), height = static_cast<int>(h);
    return true;
}


namespace {
// libpng reads a texture from the file's bytes in memory; reading past their end is an error.
struct Bytes {
    const std::string& data;
    std::size_t at = 0;
};
void read_bytes(png_structp png, png_bytep out, png_size_t n) {
    auto* b = static_cast<Bytes*>(png_get_io_ptr(png));
    if (n > b->data.size() - b->at) png_error(png, "the file ends early");
    std::memcpy(out, b->data.data() + b->at, n);
    b->at += n;
}
uint32_t big_endian(const std::string& d, std::size_t at) {
    return uint32_t{static_cast<uint8_t>(d[at])} << 24 | uint32_t{static_cast<uint8_t>(d[at + 1])} << 16 |
           uint32_t{static_cast<uint8_t>(d[at + 2])} << 8 | uint32_t{static_cast<uint8_t>(d[at + 3])};
}
// The image's size from the PNG header (signature, then the IHDR chunk: length 13, "IHDR",
// width, height), before libpng sees the file; false with the reason.
bool png_header(const std::string& d, uint32_t& width, uint32_t& height, std::string& why) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (d.size() < 8 || std::memcmp(d.data(), kSignature, 8) != 0) {
        why = "it is not a PNG file (it does not begin with PNG's signature): save the image as PNG";
        return false;
    }
    if (d.size() < 33 || big_endian(d, 8) != 13 || d.compare(12, 4, "IHDR") != 0) {
        why = "it is truncated or damaged (its PNG header is incomplete): save the image again";
        return false;
    }
    width = big_endian(d, 16), height = big_endian(d, 20);
    return true;
}
// The most a chunk before the image (a text, a colour profile) may take inflated.
constexpr png_alloc_size_t kChunkMax = 64 << 10;

// The bytes the image's rows take inflated, from its header (each row a filter byte and its
// pixels; an interlaced image's seven passes each so); 0 if the header is not one PNG allows.
uint64_t inflated_size(const std::string& d) {
    const uint64_t w = big_endian(d, 16), h = big_endian(d, 20);
    const unsigned depth = static_cast<uint8_t>(d[24]), type = static_cast<uint8_t>(d[25]);
    const unsigned interlace = static_cast<uint8_t>(d[28]);
    static const unsigned kChannels[7] = {1, 0, 3, 1, 2, 0, 4};  // by colour type
    if (type > 6 || kChannels[type] == 0 || depth == 0 || depth > 16 || interlace > 1) return 0;
    const uint64_t bits = uint64_t{kChannels[type]} * depth;
    auto rows = [&](uint64_t pw, uint64_t ph) { return pw == 0 || ph == 0 ? 0 : ph * (1 + (pw * bits + 7) / 8); };
    if (interlace == 0) return rows(w, h);
    static const unsigned kPass[7][4] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};
    uint64_t total = 0;
    for (const auto& p : kPass)
        total += rows(w > p[0] ? (w - p[0] + p[2] - 1) / p[2] : 0, h > p[1] ? (h - p[1] + p[3] - 1) / p[3] : 0);
    return total;
}

// Whether the image data (the IDAT chunks' zlib stream) inflates past what the header says
// its rows take: inflated here, before libpng, and never further than that, so that a few MiB
// of file cannot hold gigabytes to inflate (libpng, once the rows are read, inflates what
// follows them to its end). A damaged or short stream is left to libpng to report.
bool inflates_past_its_rows(const std::string& d) {
    const uint64_t most = inflated_size(d);
    if (most == 0) return false;
    z_stream z{};
    if (inflateInit(&z) != Z_OK) return false;
    Bytef out[64 << 10];
    uint64_t total = 0;
    int ret = Z_OK;
    for (std::size_t at = 8; ret == Z_OK && total <= most && at + 12 <= d.size();) {
        const std::size_t length = big_endian(d, at);
        if (length > d.size() - at - 12) break;
        if (d.compare(at + 4, 4, "IDAT") == 0) {
            z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(d.data() + at + 8));
            z.avail_in = static_cast<uInt>(length);
            while (ret == Z_OK && z.avail_in > 0 && total <= most) {
                z.next_out = out, z.avail_out = sizeof out;
                ret = inflate(&z, Z_NO_FLUSH);
                total += sizeof out - z.avail_out;
            }
        }
        at += length + 12;
    }
    inflateEnd(&z);
    return total > most;
}
}  // namespace

std::string file_identity(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return "";
    return std::to_string(static_cast<unsigned long long>(st.st_dev)) + ":" +
           std::to_string(static_cast<unsigned long long>(st.st_ino));
}

bool read_texture(const std::string& path, world::Image& out, std::string& why) {
    std::string bytes;
    if (!files::read_text_file(path, world::kImageFileLimit, "a texture's PNG file", bytes, why)) {
        why = path + ": " + why;
        return false;
    }
    uint32_t w = 0, h = 0;
    if (!png_header(bytes, w, h, why)) {
        why = path + ": " + why;
        return false;
    }
    const uint32_t most = world::kImageMaxSide;
    if (w == 0 || h == 0 || w > most || h > most) {
        why = path + ": it is " + std::to_string(w) + " x " + std::to_string(h) + " texels, " +
              (w == 0 || h == 0 ? std::string("which no image is: save it again")
                                : "over the " + std::to_string(most) + " x " + std::to_string(most) +
                                      " a texture may be: scale it down");
        return false;
    }
    if (inflates_past_its_rows(bytes)) {
        why = path + ": its compressed image data inflates to more than the " + std::to_string(w) + " x " +
              std::to_string(h) + " texels its header gives (damaged, or made to exhaust memory): save the image again";
        return false;
    }
    PngMessages messages;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &messages, png_failed, png_warned);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    std::vector<png_byte> rgb;
    std::size_t width = 0, height = 0;
    Bytes in{bytes};
    bool read = false;
    if (png && info) {
        png_set_read_fn(png, &in, read_bytes);
        png_set_user_limits(png, most, most);
        // Compressed ancillary chunks (text, colour profiles) are inflated no further than this:
        // none is used, and each could otherwise inflate to libpng's default of 8 MB.
        png_set_chunk_malloc_max(png, kChunkMax);
        read = read_guarded(png, info, width, height, rgb);
    }
    png_destroy_read_struct(&png, &info, nullptr);
    if (!read) {
        why = path + ": it is truncated or damaged" + (messages.text.empty() ? std::string() : " (libpng: " + messages.text + ")") +
              ": save the image again";
        return false;
    }
    out.width = static_cast<int>(width), out.height = static_cast<int>(height);
    out.texels.resize(width * height);
    for (std::size_t i = 0; i < width * height; ++i)
        out.texels[i] = uint32_t{rgb[3 * i]} << 16 | uint32_t{rgb[3 * i + 1]} << 8 | rgb[3 * i + 2];
    out.source = path;
    return true;
}

}  // namespace noneuclid::platform
