// write_png and read_png (app/platform.hpp) with libpng.
#include "app/platform.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

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

// The canvas's rows, top to bottom; false if a stop signal came first. A function of its own so
// that no local of write_png changes after its setjmp (g++ -O2 warns of those: -Wclobbered).
bool write_rows(png_structp png, const render::Canvas& canvas, std::vector<png_byte>& row) {
    for (int y = 0; y < canvas.height(); ++y) {
        for (int x = 0; x < canvas.width(); ++x) {
            const render::Rgb c = canvas.get(x, y);
            row[static_cast<std::size_t>(x) * 3] = c.r;
            row[static_cast<std::size_t>(x) * 3 + 1] = c.g;
            row[static_cast<std::size_t>(x) * 3 + 2] = c.b;
        }
        png_write_row(png, row.data());
        if (stop_signal() != 0) return false;
    }
    return true;
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
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        const int err = errno;
        error = "cannot write " + path + ": " +
                (std::ferror(out.file()) ? std::string(std::strerror(err)) + " (check the disk has room)"
                                         : "libpng: " + messages.text) +
                "; it is left as it was.";
        return false;  // out's destructor removes the temporary file
    }
    png_init_io(png, out.file());
    png_set_IHDR(png, info, static_cast<png_uint_32>(canvas.width()), static_cast<png_uint_32>(canvas.height()), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    if (!write_rows(png, canvas, row)) {
        png_destroy_write_struct(&png, &info);
        error = "stopped by signal " + std::to_string(stop_signal()) + " while writing " + path +
                "; it is left as it was.";
        return false;
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
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
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(f);
        error = "cannot read " + path + ": not a PNG file libpng can read" +
                (messages.text.empty() ? std::string() : " (" + messages.text + ")");
        return false;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_read_update_info(png, info);
    width = static_cast<int>(png_get_image_width(png, info));
    height = static_cast<int>(png_get_image_height(png, info));
    rgb.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, '\0');
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y)
        rows[static_cast<std::size_t>(y)] = reinterpret_cast<png_bytep>(&rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) * 3]);
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(f);
    return true;
}

}  // namespace noneuclid::platform
