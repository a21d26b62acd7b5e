// Textures in scene files, read through the platform (platform::read_texture, libpng): every
// bad image is one sentence with the place of its `texture` key and what is wrong with the image,
// an image over the size limit is refused from its header before it is decoded, and every PNG
// colour type and depth is read as the texels it holds. The PNG files are real: written here
// with libpng, or cut from such a file.
#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <algorithm>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/platform.hpp"
#include "files/scene_file.hpp"
#include "test_common.hpp"

using namespace noneuclid;
namespace fs = std::filesystem;

namespace {

using test::TempDir;

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}
std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A PNG of `color_type` and `depth` whose rows are `rows` (libpng's packing for that type).
void write_png(const std::string& path, int w, int h, int color_type, int depth, bool interlaced,
               const std::vector<std::vector<png_byte>>& rows, const std::vector<png_color>& palette = {}) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    ASSERT_EQ(setjmp(png_jmpbuf(png)), 0);
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, depth, color_type, interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!palette.empty()) png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    png_write_info(png, info);
    std::vector<png_bytep> ptrs;
    for (const auto& r : rows) ptrs.push_back(const_cast<png_bytep>(r.data()));
    png_write_image(png, ptrs.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}
// An 8-bit RGB PNG whose texel (x, y) is (x, y, x ^ y).
void write_rgb(const std::string& path, int w, int h) {
    std::vector<std::vector<png_byte>> rows(static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) rows[y].insert(rows[y].end(), {png_byte(x), png_byte(y), png_byte(x ^ y)});
    write_png(path, w, h, PNG_COLOR_TYPE_RGB, 8, false, rows);
}

// A scene with one textured body, `texture` written as given, in dir/scene.toml.
std::string scene_with(const TempDir& d, const std::string& texture, const std::string& extra = "") {
    const std::string path = d.file("scene.toml");
    write_bytes(path, "# a textured body\n[[body]]\nname = \"rock\"\nvertices = [[0.3, 0], [0.3, 120], [0.3, 240]]\n"
                      "texture = \"" + texture + "\"\n" + extra);
    return path;
}
// Loading the scene fails; the sentence, which must carry the texture key's place (line 5,
// column 11).
std::string refused(const std::string& scene) {
    world::Scene s;
    files::SceneError e;
    EXPECT_FALSE(files::load_scene_file(scene, s, e, platform::read_texture));
    EXPECT_EQ(e.line, 5);
    EXPECT_EQ(e.column, 11);
    const std::string text = e.to_string();
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
    EXPECT_NE(text.find("body 'rock': texture '"), std::string::npos) << text;
    return text;
}
const world::Image& loaded(const std::string& scene, world::Scene& s) {
    files::SceneError e;
    EXPECT_TRUE(files::load_scene_file(scene, s, e, platform::read_texture)) << e.to_string();
    EXPECT_FALSE(s.bodies.empty());
    static const world::Image none;
    return s.bodies.empty() || !s.bodies[0].texture ? none : *s.bodies[0].texture;
}

TEST(TextureFiles, AMissingFileIsNamedWithItsPlace) {
    TempDir d;
    const std::string m = refused(scene_with(d, "nope.png"));
    EXPECT_NE(m.find(d.file("nope.png") + ": cannot read it (No such file or directory)"), std::string::npos) << m;
}

TEST(TextureFiles, AFileThatIsNotAPngIsRefused) {
    TempDir d;
    write_bytes(d.file("x.png"), "GIF89a this is not a PNG at all");
    EXPECT_NE(refused(scene_with(d, "x.png")).find("is not a PNG file"), std::string::npos);
    write_bytes(d.file("empty.png"), "");
    EXPECT_NE(refused(scene_with(d, "empty.png")).find("is not a PNG file"), std::string::npos);
}

TEST(TextureFiles, ATruncatedFileIsRefused) {
    TempDir d;
    write_rgb(d.file("whole.png"), 40, 30);
    const std::string whole = read_bytes(d.file("whole.png"));
    write_bytes(d.file("half.png"), whole.substr(0, whole.size() / 2));
    std::string m = refused(scene_with(d, "half.png"));
    EXPECT_NE(m.find("half.png: it is truncated or damaged (libpng: "), std::string::npos) << m;
    write_bytes(d.file("header.png"), whole.substr(0, 20));  // the signature and part of IHDR
    m = refused(scene_with(d, "header.png"));
    EXPECT_NE(m.find("its PNG header is incomplete"), std::string::npos) << m;
    std::string damaged = whole;  // a flipped bit in the image data: its CRC no longer matches
    damaged[damaged.size() / 2] = static_cast<char>(damaged[damaged.size() / 2] ^ 0x10);
    write_bytes(d.file("damaged.png"), damaged);
    m = refused(scene_with(d, "damaged.png"));
    EXPECT_NE(m.find("damaged.png: it is truncated or damaged"), std::string::npos) << m;
}

// Over 1024 texels either way: refused from the header. The second file is only a header that
// claims 100000 x 100000: decoding it would have said "truncated", so it was never decoded.
TEST(TextureFiles, ATooLargeImageIsRefusedBeforeItIsDecoded) {
    TempDir d;
    write_rgb(d.file("wide.png"), 1100, 4);
    std::string m = refused(scene_with(d, "wide.png"));
    EXPECT_NE(m.find("it is 1100 x 4 texels, over the 1024 x 1024 a texture may be: scale it down"), std::string::npos) << m;
    const std::string whole = read_bytes(d.file("wide.png"));
    std::string huge = whole.substr(0, 33);
    for (int at : {16, 20}) huge[at] = 0, huge[at + 1] = 0x01, huge[at + 2] = static_cast<char>(0x86), huge[at + 3] = static_cast<char>(0xA0);
    write_bytes(d.file("huge.png"), huge);
    m = refused(scene_with(d, "huge.png"));
    EXPECT_NE(m.find("it is 100000 x 100000 texels, over the 1024 x 1024"), std::string::npos) << m;
    write_rgb(d.file("edge.png"), 1024, 2);  // the limit itself is fine
    world::Scene s;
    EXPECT_EQ(loaded(scene_with(d, "edge.png"), s).width, 1024);
}

TEST(TextureFiles, ADirectoryOrAnOversizedFileIsRefused) {
    TempDir d;
    fs::create_directories(d.file("dir.png"));
    EXPECT_NE(refused(scene_with(d, "dir.png")).find("it is a directory, not a file"), std::string::npos);
    write_bytes(d.file("big.png"), std::string("\x89PNG\r\n\x1a\n", 8) + std::string(4u << 20, 'x'));
    EXPECT_NE(refused(scene_with(d, "big.png")).find("over the 4 MiB a texture's PNG file may have"), std::string::npos);
}

// Every colour type and depth PNG has: the texels they hold, as 8-bit RGB.
TEST(TextureFiles, EveryColourTypeIsReadAsItsTexels) {
    TempDir d;
    world::Scene s;
    write_rgb(d.file("rgb.png"), 5, 3);
    const world::Image& rgb = loaded(scene_with(d, "rgb.png"), s);
    ASSERT_EQ(rgb.width, 5);
    ASSERT_EQ(rgb.height, 3);
    EXPECT_EQ(rgb.at(4, 2), uint32_t(4) << 16 | 2 << 8 | (4 ^ 2));

    const std::vector<png_color> pal = {{10, 20, 30}, {200, 100, 50}, {0, 255, 0}};  // 2-bit palette
    write_png(d.file("pal.png"), 4, 1, PNG_COLOR_TYPE_PALETTE, 2, false, {{png_byte(0b00011000)}}, pal);
    world::Scene s2;
    const world::Image& p = loaded(scene_with(d, "pal.png"), s2);
    ASSERT_EQ(p.width, 4);
    EXPECT_EQ(p.at(0, 0), 0x0A141Eu);
    EXPECT_EQ(p.at(1, 0), 0xC86432u);
    EXPECT_EQ(p.at(2, 0), 0x00FF00u);
    EXPECT_EQ(p.at(3, 0), 0x0A141Eu);

    // 16-bit grey with alpha: the top byte of each grey, alpha dropped.
    write_png(d.file("ga16.png"), 2, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 16, false, {{0x12, 0x34, 0x00, 0x00, 0xAB, 0xCD, 0xFF, 0xFF}});
    world::Scene s3;
    const world::Image& g = loaded(scene_with(d, "ga16.png"), s3);
    EXPECT_EQ(g.at(0, 0), 0x121212u);
    EXPECT_EQ(g.at(1, 0), 0xABABABu);

    // 8-bit RGBA, interlaced (Adam7).
    std::vector<std::vector<png_byte>> rows(9);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 9; ++x) rows[y].insert(rows[y].end(), {png_byte(x * 20), png_byte(y * 20), 7, png_byte(x * y)});
    write_png(d.file("rgba.png"), 9, 9, PNG_COLOR_TYPE_RGB_ALPHA, 8, true, rows);
    world::Scene s4;
    const world::Image& a = loaded(scene_with(d, "rgba.png"), s4);
    ASSERT_EQ(a.width, 9);
    EXPECT_EQ(a.at(8, 5), uint32_t(160) << 16 | 100 << 8 | 7);
}

// Relative to the scene file; one file named by two bodies (and the game) is read once.
TEST(TextureFiles, PathsAreRelativeToTheSceneAndReadOnce) {
    TempDir d;
    fs::create_directories(d.file("art"));
    write_rgb(d.file("art/r.png"), 8, 8);
    const std::string scene = scene_with(d, "art/r.png",
                                         "[[body]]\nname = \"ship\"\nvertices = [[0.12, 0], [0.08, 140], [0.08, 220]]\n"
                                         "texture = \"art/r.png\"\ntexture_scale = 2\ntexture_filter = \"bilinear\"\n"
                                         "[game]\nasteroid_texture = \"art/r.png\"\n");
    world::Scene s;
    loaded(scene, s);
    ASSERT_GE(s.bodies.size(), 3u);
    EXPECT_EQ(s.bodies[0].texture, s.bodies[1].texture);
    EXPECT_EQ(s.bodies[1].texture_scale, 2);
    EXPECT_TRUE(s.bodies[1].texture_bilinear);
    EXPECT_EQ(s.bodies.back().role, world::BodyKind::bullet);
    bool asteroid = false;
    for (const world::SceneBody& b : s.bodies)
        if (b.role == world::BodyKind::asteroid) {
            asteroid = true;
            EXPECT_EQ(b.texture, s.bodies[0].texture);
        }
    EXPECT_TRUE(asteroid);
}

// The built-in images need no file (nor a reader); anything else does.
TEST(TextureFiles, BuiltInImagesNeedNoFile) {
    world::Scene s;
    files::SceneError e;
    const std::string body = "[[body]]\nvertices = [[0.3, 0], [0.3, 120], [0.3, 240]]\n";
    ASSERT_TRUE(files::parse_scene(body + "texture = \"builtin:rock\"\n", "s.toml", s, e)) << e.to_string();
    EXPECT_EQ(s.bodies[0].texture->width, 64);
    EXPECT_FALSE(files::parse_scene(body + "texture = \"builtin:marble\"\n", "s.toml", s, e));
    EXPECT_NE(e.message.find("no such built-in image (builtin:checker, builtin:rock)"), std::string::npos) << e.message;
    EXPECT_FALSE(files::parse_scene(body + "texture = \"a.png\"\n", "s.toml", s, e));
    EXPECT_NE(e.message.find("image files cannot be read here"), std::string::npos) << e.message;
    EXPECT_FALSE(files::parse_scene(body + "fill = \"#123\"\n", "s.toml", s, e));
    EXPECT_EQ(e.line, 3);
    EXPECT_FALSE(files::parse_scene(body + "closed = false\nfill = \"#123456\"\n", "s.toml", s, e));
    EXPECT_NE(e.message.find("a fill or a texture needs a closed outline of 3 or more vertices"), std::string::npos);
    EXPECT_FALSE(files::parse_scene(body + "texture = \"builtin:rock\"\ntexture_filter = \"cubic\"\n", "s.toml", s, e));
    EXPECT_NE(e.message.find("'texture_filter' = \"nearest\" or \"bilinear\""), std::string::npos) << e.message;
    EXPECT_FALSE(files::parse_scene(body + "texture = \"builtin:rock\"\ntexture_scale = 0\n", "s.toml", s, e));
    ASSERT_TRUE(files::parse_scene(body + "fill = \"#102030\"\n", "s.toml", s, e)) << e.to_string();
    EXPECT_TRUE(s.bodies[0].filled);
    EXPECT_EQ(s.bodies[0].fill, (world::Rgb{16, 32, 48}));
}

// A scene of one body per spelling, each naming its texture as spelt.
std::string scene_of_spellings(const TempDir& d, const std::vector<std::string>& spellings) {
    std::string text;
    for (const std::string& t : spellings)
        text += "[[body]]\nvertices = [[0.05, 0], [0.05, 120], [0.05, 240]]\ntexture = \"" + t + "\"\n";
    const std::string path = d.file("many.toml");
    write_bytes(path, text);
    return path;
}

// One 1024 x 1024 PNG named by 2,048 bodies, each spelling its path differently (and through a
// link): decoded once, one image shared by every body, not 2,048 images of 4 MiB (issue 33: that
// was 8 GiB and std::bad_alloc).
TEST(TextureFiles, OneFileUnderManySpellingsIsDecodedOnce) {
    TempDir d;
    fs::create_directories(d.file("art"));
    write_rgb(d.file("art/t.png"), 1024, 1024);
    fs::create_symlink("t.png", d.file("art/link.png"));
    std::vector<std::string> spellings;
    for (int i = 0; i < 2046; ++i) {  // "art/t.png", "./art/t.png", ".//art/./t.png", ...
        std::string s;
        for (int bit = 0; bit < 11; ++bit)
            if (i >> bit & 1) s += bit % 2 ? ".//" : "./";
        spellings.push_back(s + (i % 3 == 0 ? "art/t.png" : i % 3 == 1 ? "art/./t.png" : "art//t.png"));
    }
    spellings.push_back("art/link.png");
    spellings.push_back(d.file("art/t.png"));  // absolute
    world::Scene s;
    files::SceneError e;
    ASSERT_TRUE(files::load_scene_file(scene_of_spellings(d, spellings), s, e, platform::read_texture,
                                       platform::file_identity))
        << e.to_string();
    ASSERT_EQ(s.bodies.size(), 2048u);
    for (const world::SceneBody& b : s.bodies) ASSERT_EQ(b.texture, s.bodies[0].texture) << b.name;
    EXPECT_EQ(s.bodies[0].texture->at(1000, 3), uint32_t(1000 & 255) << 16 | 3 << 8 | ((1000 ^ 3) & 255));
    // Two files with the same bytes are two images.
    fs::copy_file(d.file("art/t.png"), d.file("art/copy.png"));
    ASSERT_TRUE(files::load_scene_file(scene_of_spellings(d, {"art/t.png", "art/copy.png"}), s, e,
                                       platform::read_texture, platform::file_identity))
        << e.to_string();
    EXPECT_NE(s.bodies[0].texture, s.bodies[1].texture);
    EXPECT_EQ(platform::file_identity(d.file("art/nothing.png")), "");
}

// Images decoded count against the world's budget (64 MiB: sixteen of the largest size) as the
// scene is read: the seventeenth distinct 1024 x 1024 file is refused at its place, before any
// later one is decoded.
TEST(TextureFiles, DecodedImagesOverTheBudgetAreRefused) {
    TempDir d;
    write_rgb(d.file("c0.png"), 1024, 1024);
    std::vector<std::string> names{"c0.png"};
    for (int i = 1; i < 18; ++i) {
        names.push_back("c" + std::to_string(i) + ".png");
        fs::copy_file(d.file("c0.png"), d.file(names.back()));
    }
    world::Scene s;
    files::SceneError e;
    ASSERT_TRUE(files::load_scene_file(scene_of_spellings(d, std::vector<std::string>(names.begin(), names.begin() + 16)),
                                       s, e, platform::read_texture, platform::file_identity))
        << e.to_string();
    EXPECT_FALSE(files::load_scene_file(scene_of_spellings(d, names), s, e, platform::read_texture, platform::file_identity));
    EXPECT_EQ(e.line, 3 * 17);  // the seventeenth body's texture
    EXPECT_NE(e.message.find("texture 'c16.png': the scene's texture images would take 68 MiB decoded, over the 64 MiB "
                             "a world may have: use fewer or smaller images"),
              std::string::npos)
        << e.message;
    EXPECT_EQ(68 << 20, 17 * 1024 * 1024 * 4);  // 17 images of 1024 x 1024 texels, 4 bytes each
}

// A PNG chunk: length, type, data, CRC.
std::string png_chunk(const char* type, const std::string& data) {
    auto be32 = [](uint32_t v) {
        return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
    };
    const std::string body = std::string(type, 4) + data;
    const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()));
    return be32(static_cast<uint32_t>(data.size())) + body + be32(static_cast<uint32_t>(crc));
}
// The first IDAT chunk of png_bomb: at most its first 4 KiB.
constexpr std::size_t kBombFirstIdat = 4096;
// A 16 x 16 8-bit RGB PNG whose image data is the zlib stream of its rows (every byte 0: filter
// none, black) followed by `extra` more zero bytes: a stream that inflates far past what the
// header promises, as a bomb does.
std::string png_bomb(std::size_t extra) {
    const std::size_t rows = 16 * (1 + 16 * 3);
    z_stream z{};
    EXPECT_EQ(deflateInit(&z, 9), Z_OK);
    const std::vector<Bytef> zeros(1 << 20, 0);
    std::string idat;
    std::vector<Bytef> out(1 << 16);
    for (std::size_t left = rows + extra; ;) {
        const std::size_t n = std::min(left, zeros.size());
        left -= n;
        z.next_in = const_cast<Bytef*>(zeros.data()), z.avail_in = static_cast<uInt>(n);
        int ret;
        do {
            z.next_out = out.data(), z.avail_out = static_cast<uInt>(out.size());
            ret = deflate(&z, left == 0 ? Z_FINISH : Z_NO_FLUSH);
            idat.append(reinterpret_cast<const char*>(out.data()), out.size() - z.avail_out);
        } while (z.avail_out == 0 || (left == 0 && ret != Z_STREAM_END));
        if (left == 0) break;
    }
    deflateEnd(&z);
    const std::string ihdr{0, 0, 0, 16, 0, 0, 0, 16, 8, 2, 0, 0, 0};  // 16 x 16, 8-bit RGB
    // Two IDAT chunks when the stream is long enough: the reader follows the stream across them.
    const std::size_t first = std::min(idat.size(), kBombFirstIdat);
    return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("IDAT", idat.substr(0, first)) +
           (first < idat.size() ? png_chunk("IDAT", idat.substr(first)) : std::string()) + png_chunk("IEND", "");
}

// Image data that inflates past what the header promises is refused, inflated no further than
// that (issue 33: a 4 MiB file that inflated to 4 GiB took 11 s of CPU before it was accepted;
// docs/performance.md has the times). The same stream without the extra bytes is read.
TEST(TextureFiles, ImageDataThatInflatesPastItsRowsIsRefused) {
    TempDir d;
    const std::string bomb = png_bomb(std::size_t{64} << 20);
    ASSERT_LT(bomb.size(), std::size_t{1} << 20);  // 64 MiB of zeros in well under 1 MiB
    write_bytes(d.file("bomb.png"), bomb);
    const std::string m = refused(scene_with(d, "bomb.png"));
    EXPECT_NE(m.find("bomb.png: its compressed image data inflates to more than the 16 x 16 texels its header gives "
                     "(damaged, or made to exhaust memory): save the image again"),
              std::string::npos)
        << m;
    write_bytes(d.file("plain.png"), png_bomb(0));
    world::Scene s;
    const world::Image& plain = loaded(scene_with(d, "plain.png"), s);
    ASSERT_EQ(plain.width, 16);
    ASSERT_EQ(plain.texels.size(), 256u);
    for (uint32_t t : plain.texels) EXPECT_EQ(t, 0u);
}

}  // namespace
