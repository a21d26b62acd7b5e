// Animated GIFs (platform/files/gif_file.cpp, giflib): frames written and read back exactly
// (at most 256 colours a frame), with their delays; a bad path is one sentence and leaves
// nothing; a writer dropped unfinished or stopped leaves the target as it was.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/platform.hpp"
#include "render/canvas.hpp"
#include "test_common.hpp"

using namespace noneuclid;

namespace {

using test::TempDir;

constexpr int kW = 64, kH = 48;

// Frame k: a background and a k-dependent pattern in 3 + k colours.
void paint(const render::Canvas& c, int k) {
    c.clear({6, 8, 14});
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            if ((x + y + k) % 7 == 0) c.set(x, y, {static_cast<uint8_t>(40 * ((x / 8 + k) % 3 + k)), 200, static_cast<uint8_t>(10 * k)});
}
std::string rgb_of(const render::Canvas& c) {
    std::string out;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const render::Rgb p = c.get(x, y);
            out += static_cast<char>(p.r), out += static_cast<char>(p.g), out += static_cast<char>(p.b);
        }
    return out;
}
// Files in d other than `except`.
int others(const std::filesystem::path& d, const std::string& except) {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(d)) n += e.path().filename() != except;
    return n;
}

TEST(Gif, FramesAndDelaysReadBackExactly) {
    const TempDir tmp;
    const auto& dir = tmp.path;
    const std::string path = (dir / "a.gif").string();
    std::vector<uint32_t> px(kW * kH);
    const render::Canvas c(reinterpret_cast<uint8_t*>(px.data()), kW, kH, kW * 4, render::PixelFormat::xrgb8888());
    std::string error;
    auto gif = platform::open_gif(path, kW, kH, error);
    ASSERT_TRUE(gif) << error;
    std::vector<std::string> want;
    const int delays[] = {2, 3, 5};
    for (int k = 0; k < 3; ++k) {
        paint(c, k);
        want.push_back(rgb_of(c));
        ASSERT_TRUE(gif->frame(c, delays[k], error)) << error;
    }
    EXPECT_FALSE(std::filesystem::exists(path));  // not before finish
    ASSERT_TRUE(gif->finish(error)) << error;
    int w = 0, h = 0;
    std::vector<platform::GifFrame> frames;
    ASSERT_TRUE(platform::read_gif(path, w, h, frames, error)) << error;
    EXPECT_EQ(w, kW);
    EXPECT_EQ(h, kH);
    ASSERT_EQ(frames.size(), 3u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(frames[static_cast<std::size_t>(k)].rgb, want[static_cast<std::size_t>(k)]) << "frame " << k;
        EXPECT_EQ(frames[static_cast<std::size_t>(k)].centiseconds, delays[k]) << "frame " << k;
    }
    EXPECT_EQ(others(dir, "a.gif"), 0);  // no temporary file left
}

// A GIF frame's delay is 16 bits: 65535 centiseconds (655.35 s) is written and read back as it
// is; 65536 would wrap to 0 and is refused with one sentence, the target left as it was.
TEST(Gif, ADelayPastSixteenBitsIsRefusedNotWrapped) {
    const TempDir tmp;
    const std::string path = (tmp.path / "long.gif").string();
    std::vector<uint32_t> px(kW * kH);
    const render::Canvas c(reinterpret_cast<uint8_t*>(px.data()), kW, kH, kW * 4, render::PixelFormat::xrgb8888());
    paint(c, 2);
    std::string error;
    auto gif = platform::open_gif(path, kW, kH, error);
    ASSERT_TRUE(gif) << error;
    ASSERT_TRUE(gif->frame(c, 65535, error)) << error;
    ASSERT_TRUE(gif->finish(error)) << error;
    int w = 0, h = 0;
    std::vector<platform::GifFrame> frames;
    ASSERT_TRUE(platform::read_gif(path, w, h, frames, error)) << error;
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0].centiseconds, 65535);

    { std::ofstream(path) << "the earlier file"; }
    gif = platform::open_gif(path, kW, kH, error);
    ASSERT_TRUE(gif) << error;
    EXPECT_FALSE(gif->frame(c, 65536, error));
    EXPECT_NE(error.find("a frame's delay of 65536 centiseconds is past the 655.35 s"), std::string::npos) << error;
    gif.reset();
    std::ifstream in(path);
    std::string text;
    std::getline(in, text);
    EXPECT_EQ(text, "the earlier file");
    EXPECT_EQ(others(tmp.path, "long.gif"), 0);
}

TEST(Gif, AMissingDirectoryIsOneSentenceAndLeavesNothing) {
    std::string error;
    EXPECT_FALSE(platform::open_gif("/nonexistent/dir/x.gif", kW, kH, error));
    EXPECT_NE(error.find("cannot write /nonexistent/dir/x.gif: No such file or directory"), std::string::npos) << error;
    EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir"));
}

TEST(Gif, AWriterDroppedUnfinishedLeavesTheOldFile) {
    const TempDir tmp;
    const auto& dir = tmp.path;
    const std::string path = (dir / "b.gif").string();
    { std::ofstream(path) << "the earlier file"; }
    std::vector<uint32_t> px(kW * kH);
    const render::Canvas c(reinterpret_cast<uint8_t*>(px.data()), kW, kH, kW * 4, render::PixelFormat::xrgb8888());
    paint(c, 1);
    std::string error;
    {
        auto gif = platform::open_gif(path, kW, kH, error);
        ASSERT_TRUE(gif) << error;
        ASSERT_TRUE(gif->frame(c, 2, error)) << error;
    }  // dropped without finish
    std::ifstream in(path);
    std::string text;
    std::getline(in, text);
    EXPECT_EQ(text, "the earlier file");
    EXPECT_EQ(others(dir, "b.gif"), 0);
}

}  // namespace
