// Console font files and the HUD font (platform/files/console_font.hpp): gzip and plain PSF
// files written by the test and loaded back pixel for pixel, every bad file named in one
// sentence, and the HUD's choice of font ($NONEUCLID_FONT, the console fonts, the built-in one).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../../render/psf_bytes.hpp"
#include "files/console_font.hpp"
#include "render/font.hpp"
#include "test_common.hpp"

using namespace noneuclid::render;
using namespace noneuclid::test;

namespace {

namespace fs = std::filesystem;
using noneuclid::platform::default_hud_font;
using noneuclid::platform::load_console_font;
using noneuclid::platform::LoadedFont;

void write_gz(const std::string& path, const std::vector<uint8_t>& bytes) {
    gzFile f = gzopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr) << path;
    ASSERT_EQ(gzwrite(f, bytes.data(), unsigned(bytes.size())), int(bytes.size()));
    ASSERT_EQ(gzclose(f), Z_OK);
}

void write_plain(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    ASSERT_TRUE(out.good()) << path;
}

// The loaded font's pixels are the file's, read through its own bytes.
void expect_loaded(const LoadedFont& lf, int width, int height, int count) {
    EXPECT_EQ(lf.font.width, width);
    EXPECT_EQ(lf.font.height, height);
    EXPECT_EQ(lf.font.glyph_count, count);
    ASSERT_FALSE(lf.bytes.empty());
    EXPECT_GE(lf.font.glyphs, lf.bytes.data());
    EXPECT_LE(lf.font.glyphs + std::size_t(count * height * lf.font.bytes_per_row),
              lf.bytes.data() + lf.bytes.size());
    expect_font_matches_pattern(lf.font);
}

}  // namespace

TEST(FontConsole, LoadsGzipAndPlainFiles) {
    TempDir dir;
    Psf2 p;
    write_gz(dir.file("ten.psf.gz"), make_psf2(p));
    write_plain(dir.file("sixteen.psf"), make_psf1(16, 1));
    LoadedFont a, b;
    std::string error;
    ASSERT_TRUE(load_console_font(dir.file("ten.psf.gz"), a, error)) << error;
    expect_loaded(a, 10, 12, 100);
    EXPECT_EQ(a.source, dir.file("ten.psf.gz"));
    ASSERT_TRUE(load_console_font(dir.file("sixteen.psf"), b, error)) << error;
    expect_loaded(b, 8, 16, 512);

    // Moving keeps font.glyphs pointing into the (moved) bytes.
    LoadedFont moved = std::move(a);
    expect_loaded(moved, 10, 12, 100);
    LoadedFont assigned;
    assigned = std::move(moved);
    expect_loaded(assigned, 10, 12, 100);
}

TEST(FontConsole, ErrorsNameTheFile) {
    TempDir dir;
    LoadedFont f;
    std::string error;
    const std::string missing = dir.file("no-such-font.psf.gz");
    EXPECT_FALSE(load_console_font(missing, f, error));
    EXPECT_EQ(error, missing + ": cannot open the font file (No such file or directory)");

    write_gz(dir.file("text.psf.gz"), {'h', 'e', 'l', 'l', 'o', '\n'});
    EXPECT_FALSE(load_console_font(dir.file("text.psf.gz"), f, error));
    EXPECT_EQ(error, dir.file("text.psf.gz") + ": not a PSF font (bad magic number)");

    write_plain(dir.file("short.psf"), make_psf1(16, 0, 100));
    EXPECT_FALSE(load_console_font(dir.file("short.psf"), f, error));
    EXPECT_EQ(error, dir.file("short.psf")
                         + ": the PSF font is truncated: 4096 bytes of glyphs expected, 100 found");

    // A gzip stream cut short.
    write_gz(dir.file("cut.psf.gz"), make_psf1(16, 0));
    {
        std::ifstream in(dir.file("cut.psf.gz"), std::ios::binary);
        std::vector<char> all((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
        all.resize(all.size() / 2);
        std::ofstream out(dir.file("cut.psf.gz"), std::ios::binary | std::ios::trunc);
        out.write(all.data(), std::streamsize(all.size()));
    }
    EXPECT_FALSE(load_console_font(dir.file("cut.psf.gz"), f, error));
    EXPECT_EQ(error.rfind(dir.file("cut.psf.gz") + ": cannot read the font file (", 0), 0u)
        << error;

    EXPECT_FALSE(load_console_font(dir.path.string(), f, error));  // a directory
    EXPECT_EQ(error, dir.path.string() + ": the font file is a directory, not a file") << error;
    EXPECT_FALSE(load_console_font("/dev/null", f, error));  // a device
    EXPECT_EQ(error, "/dev/null: the font file is a device, not a file") << error;

    EXPECT_EQ(error.find('\n'), std::string::npos);
    EXPECT_TRUE(f.bytes.empty());
    EXPECT_EQ(f.font.glyphs, nullptr);
}

// A FIFO named as a font (--font, $NONEUCLID_FONT, a recording's font) is refused at once: a
// read would wait for a writer that may never come. (Were it waited on, this test would hang
// until ctest's timeout ends it as failed.)
TEST(FontConsole, AFifoIsRefusedNotWaitedOn) {
    TempDir dir;
    const std::string fifo = dir.file("font.psf");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    LoadedFont f;
    std::string error, note;
    EXPECT_FALSE(load_console_font(fifo, f, error));
    EXPECT_EQ(error, fifo + ": the font file is a pipe (FIFO), not a file (it is not waited on)");
    EXPECT_FALSE(noneuclid::platform::hud_font(fifo, f, error));
    EXPECT_EQ(error.rfind(fifo + ": the font file is a pipe (FIFO)", 0), 0u) << error;
    ASSERT_EQ(setenv("NONEUCLID_FONT", fifo.c_str(), 1), 0);
    TempDir empty;
    f = default_hud_font(&note, empty.path.string());
    ASSERT_EQ(unsetenv("NONEUCLID_FONT"), 0);
    EXPECT_EQ(f.source, "built-in 6x8");
    EXPECT_NE(note.find("since NONEUCLID_FONT is unusable (" + fifo + ": the font file is a pipe (FIFO)"), std::string::npos)
        << note;
}

TEST(FontConsole, HudFontChoice) {
    TempDir dir, empty;
    const std::string env_font = dir.file("mine.psf");
    write_plain(env_font, make_psf1(14, 0));
    std::string note;

    // $NONEUCLID_FONT first.
    ASSERT_EQ(setenv("NONEUCLID_FONT", env_font.c_str(), 1), 0);
    LoadedFont f = default_hud_font(&note, empty.path.string());
    EXPECT_EQ(f.source, env_font);
    EXPECT_EQ(f.font.height, 14);
    EXPECT_EQ(note, "HUD font: " + env_font + " (8x14), chosen by NONEUCLID_FONT.");

    // An unusable $NONEUCLID_FONT and no console fonts: the built-in font, and the note says why.
    ASSERT_EQ(setenv("NONEUCLID_FONT", dir.file("absent.psf").c_str(), 1), 0);
    f = default_hud_font(&note, empty.path.string());
    EXPECT_EQ(f.source, "built-in 6x8");
    EXPECT_EQ(f.font.glyphs, builtin_font().glyphs);
    EXPECT_EQ(note, "HUD font: the built-in 6x8 font, as no usable console font is in " +
                        empty.path.string() +
                        " (Debian's console-setup-linux provides them), since NONEUCLID_FONT is "
                        "unusable (" + dir.file("absent.psf") +
                        ": cannot open the font file (No such file or directory)).");
    ASSERT_EQ(unsetenv("NONEUCLID_FONT"), 0);

    // Any font in the directory, in name order, skipping unusable ones.
    TempDir fonts;
    write_gz(fonts.file("Aaa-broken.psf.gz"), {1, 2, 3});
    write_gz(fonts.file("Bbb-Small12.psf.gz"), make_psf1(12, 0));
    write_gz(fonts.file("Ccc-Large20.psf.gz"), make_psf1(20, 0));
    write_plain(fonts.file("Abc-not-gz.psf"), make_psf1(10, 0));
    f = default_hud_font(&note, fonts.path.string());
    EXPECT_EQ(f.source, fonts.file("Bbb-Small12.psf.gz"));
    EXPECT_EQ(note, "HUD font: " + fonts.file("Bbb-Small12.psf.gz")
                        + " (8x12), the first usable font in " + fonts.path.string()
                        + " (none of the preferred Terminus or Fixed 16-pixel fonts is there).");
    expect_loaded(f, 8, 12, 256);

    // A preferred font wins, in the documented order.
    write_gz(fonts.file("Uni2-Fixed16.psf.gz"), make_psf1(16, 1));
    f = default_hud_font(&note, fonts.path.string());
    EXPECT_EQ(f.source, fonts.file("Uni2-Fixed16.psf.gz"));
    write_gz(fonts.file("Uni2-Terminus16.psf.gz"), make_psf1(16, 0));
    f = default_hud_font(nullptr, fonts.path.string());
    EXPECT_EQ(f.source, fonts.file("Uni2-Terminus16.psf.gz"));
    write_gz(fonts.file("Lat15-Terminus16.psf.gz"), make_psf2({}));
    f = default_hud_font(&note, fonts.path.string());
    EXPECT_EQ(f.source, fonts.file("Lat15-Terminus16.psf.gz"));
    EXPECT_EQ(note, "HUD font: " + fonts.file("Lat15-Terminus16.psf.gz")
                        + " (10x12), the preferred console font.");
    expect_loaded(f, 10, 12, 100);

    // A missing directory is like an empty one.
    f = default_hud_font(&note, fonts.file("no-such-dir"));
    EXPECT_EQ(f.source, "built-in 6x8");
}
