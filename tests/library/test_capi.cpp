// The C interface (src/capi/noneuclid.h): its pictures are the program's (app::render_picture,
// what `noneuclid render` draws) byte for byte in every pixel format it names; bad input of
// every kind is a status and one sentence, with the caller's memory untouched; the controls
// and K act as in the program; and stepping, drawing and reading allocate nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "app/picture.hpp"
#include "app/setup.hpp"
#include "capi/noneuclid.h"
#include "counting_new.hpp"
#include "render/font.hpp"

namespace {

using namespace noneuclid;

// A world that frees itself.
struct World {
    nw_world* w = nullptr;
    ~World() { nw_world_free(w); }
};

// The last error is one sentence: one line, ending with a full stop, naming `function`.
void expect_sentence(const char* function) {
    const std::string e = nw_last_error();
    SCOPED_TRACE(e);
    EXPECT_EQ(e.rfind(std::string(function) + ": ", 0), 0u);
    EXPECT_EQ(e.find('\n'), std::string::npos);
    EXPECT_EQ(e.back(), '.');
}

// The program's picture of `scene` after `frames` steps in `format` (app::render_picture).
std::vector<uint8_t> program_picture(const char* scene, long frames, int width, int height, render::PixelFormat format) {
    app::Options o;
    o.scene = scene, o.frames = frames, o.width = width, o.height = height, o.format = format;
    app::Picture picture;
    app::render_picture(o, app::load_scene(o), nullptr, render::builtin_font(), picture);
    return picture.pixels;
}

TEST(CApi, Version) {
    EXPECT_STREQ(nw_version(), NONEUCLID_VERSION);
    EXPECT_EQ(nw_version_number(), NW_VERSION_NUMBER);
    EXPECT_EQ(std::to_string(NW_VERSION_MAJOR) + "." + std::to_string(NW_VERSION_MINOR) + "." +
                  std::to_string(NW_VERSION_PATCH),
              NONEUCLID_VERSION);
}

TEST(CApi, DrawsTheProgramsPictureInEveryFormat) {
    using P = render::PixelFormat;
    for (const P& f : {P::xrgb8888(), P::rgb565(), P::rgb888(), P::bgr565(), P::xbgr8888(), P::bgr888(), P::rgba8888()}) {
        SCOPED_TRACE(f.name);
        World w;
        ASSERT_EQ(nw_world_from_name("kiosk", nullptr, &w.w), NW_OK) << nw_last_error();
        ASSERT_EQ(nw_step(w.w, 30), NW_OK);
        int bytes = 0;
        ASSERT_EQ(nw_format_bytes(f.name, &bytes), NW_OK);
        EXPECT_EQ(bytes, f.bytes_per_pixel());
        std::vector<uint8_t> ours(static_cast<std::size_t>(160 * 120 * bytes), 0xA5);
        ASSERT_EQ(nw_draw(w.w, ours.data(), ours.size(), 160, 120, 0, f.name), NW_OK) << nw_last_error();
        EXPECT_TRUE(ours == program_picture("kiosk", 30, 160, 120, f));
    }
}

TEST(CApi, SceneTextIsTheSceneFile) {
    // lesson.toml through nw_world_from_text, drawn antialiased in the stereographic projection,
    // is the program's picture of that file with --aa --projection stereographic.
    std::string text;
    {
        std::FILE* f = std::fopen(NONEUCLID_TEST_DATA "/lesson.toml", "rb");
        ASSERT_NE(f, nullptr);
        char buf[4096];
        for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
        std::fclose(f);
    }
    World w;
    ASSERT_EQ(nw_world_from_text(text.data(), text.size(), "double", &w.w), NW_OK) << nw_last_error();
    ASSERT_EQ(nw_set_view(w.w, "stereographic", 1), NW_OK);
    ASSERT_EQ(nw_step(w.w, 20), NW_OK);
    std::vector<uint8_t> ours(200 * 150 * 4);
    ASSERT_EQ(nw_draw(w.w, ours.data(), ours.size(), 200, 150, 0, "xrgb8888"), NW_OK);
    app::Options o;
    o.scene = NONEUCLID_TEST_DATA "/lesson.toml", o.frames = 20, o.width = 200, o.height = 150, o.aa = true;
    o.projection = geo::Projection::stereographic;
    o.engine = world::engine_named("double");
    app::Picture picture;
    app::render_picture(o, app::load_scene(o), nullptr, render::builtin_font(), picture);
    EXPECT_TRUE(ours == picture.pixels);
}

TEST(CApi, StrideLeavesThePaddingAlone) {
    World w;
    ASSERT_EQ(nw_world_from_name("fig1", nullptr, &w.w), NW_OK);
    std::vector<uint8_t> packed(100 * 80 * 2);
    ASSERT_EQ(nw_draw(w.w, packed.data(), packed.size(), 100, 80, 0, "rgb565"), NW_OK);
    const std::ptrdiff_t stride = 100 * 2 + 14;
    std::vector<uint8_t> padded(static_cast<std::size_t>(stride) * 80, 0x5A);
    ASSERT_EQ(nw_draw(w.w, padded.data(), padded.size(), 100, 80, stride, "rgb565"), NW_OK);
    for (int y = 0; y < 80; ++y) {
        EXPECT_EQ(std::memcmp(&padded[static_cast<std::size_t>(y * stride)], &packed[static_cast<std::size_t>(y * 200)], 200), 0);
        for (int x = 200; x < stride; ++x) EXPECT_EQ(padded[static_cast<std::size_t>(y * stride + x)], 0x5A);
    }
}

// One long list on purpose: every function's every refusal, each a line, read top to bottom.
TEST(CApi, BadInputIsAStatusAndASentence) {
    nw_world* w = reinterpret_cast<nw_world*>(1);
    EXPECT_EQ(nw_world_from_name("no such scene", nullptr, &w), NW_ERR_SCENE);
    EXPECT_EQ(w, nullptr);  // out is cleared on a failure
    expect_sentence("nw_world_from_name");
    EXPECT_NE(std::string(nw_last_error()).find("kiosk"), std::string::npos);  // the names to choose from
    EXPECT_EQ(nw_world_from_name("kiosk", "abacus", &w), NW_ERR_NAME);
    expect_sentence("nw_world_from_name");
    EXPECT_EQ(nw_world_from_name("kiosk", "paper", &w), NW_ERR_NAME);  // (the program's, not the C interface's)
    EXPECT_EQ(nw_world_from_name(nullptr, nullptr, &w), NW_ERR_NULL);
    EXPECT_EQ(nw_world_from_name("kiosk", nullptr, nullptr), NW_ERR_NULL);
    expect_sentence("nw_world_from_name");
    EXPECT_EQ(nw_world_from_name("lens", nullptr, &w), NW_ERR_SCENE);  // an uneven world: not here yet
    EXPECT_NE(std::string(nw_last_error()).find("with [[bump]] tables"), std::string::npos) << nw_last_error();
    EXPECT_EQ(nw_world_from_name("space", nullptr, &w), NW_ERR_SCENE);  // the 3D world: not here yet
    EXPECT_NE(std::string(nw_last_error()).find("a three-dimensional space"), std::string::npos) << nw_last_error();
    expect_sentence("nw_world_from_name");

    const char bad[] = "curvature = 2.0\n";
    EXPECT_EQ(nw_world_from_text(bad, sizeof bad - 1, nullptr, &w), NW_ERR_SCENE);
    EXPECT_EQ(std::string(nw_last_error()).rfind("scene text:1:", 0), 0u) << nw_last_error();
    const char garbage[] = "[[body]\n\x01\xff";
    EXPECT_EQ(nw_world_from_text(garbage, sizeof garbage - 1, nullptr, &w), NW_ERR_SCENE);
    EXPECT_EQ(nw_world_from_text(nullptr, 0, nullptr, &w), NW_ERR_NULL);
    std::string huge(std::size_t{1} << 21, ' ');
    EXPECT_EQ(nw_world_from_text(huge.data(), huge.size(), nullptr, &w), NW_ERR_SIZE);
    expect_sentence("nw_world_from_text");

    World k;
    ASSERT_EQ(nw_world_from_name("kiosk", nullptr, &k.w), NW_OK);
    std::vector<uint8_t> buf(64 * 48 * 4, 0x77);
    auto untouched = [&] {
        for (uint8_t b : buf)
            if (b != 0x77) return false;
        return true;
    };
    EXPECT_EQ(nw_draw(k.w, nullptr, buf.size(), 64, 48, 0, "rgb565"), NW_ERR_NULL);
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size(), 64, 48, 0, "rgb555"), NW_ERR_NAME);
    expect_sentence("nw_draw");
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size(), 64, 48, 0, nullptr), NW_ERR_NULL);
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size(), 0, 48, 0, "rgb565"), NW_ERR_SIZE);
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size(), 64, -1, 0, "rgb565"), NW_ERR_SIZE);
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size(), 9000, 1, 0, "rgb565"), NW_ERR_SIZE);
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size(), 64, 48, 0, "xrgb8888"), NW_OK);  // exactly fits
    std::fill(buf.begin(), buf.end(), 0x77);
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size() - 1, 64, 48, 0, "xrgb8888"), NW_ERR_SIZE);  // one byte short
    expect_sentence("nw_draw");
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size(), 64, 48, 64 * 4 - 1, "xrgb8888"), NW_ERR_SIZE);  // rows overlap
    EXPECT_EQ(nw_draw(k.w, buf.data(), buf.size(), 64, 48, std::numeric_limits<ptrdiff_t>::max() / 2, "rgb565"),
              NW_ERR_SIZE);
    EXPECT_TRUE(untouched());

    EXPECT_EQ(nw_set_curvature(k.w, 1.5), NW_ERR_RANGE);
    expect_sentence("nw_set_curvature");
    EXPECT_EQ(nw_set_curvature(k.w, std::nan("")), NW_ERR_RANGE);
    EXPECT_EQ(nw_step(k.w, -1), NW_ERR_RANGE);
    EXPECT_EQ(nw_control(k.w, "jump", 1), NW_ERR_NAME);
    expect_sentence("nw_control");
    EXPECT_NE(std::string(nw_last_error()).find("thrust"), std::string::npos);
    EXPECT_EQ(nw_set_view(k.w, "mercator", 0), NW_ERR_NAME);
    nw_body b;
    EXPECT_EQ(nw_body_at(k.w, -1, &b), NW_ERR_RANGE);
    EXPECT_EQ(nw_body_at(k.w, 1 << 20, &b), NW_ERR_RANGE);
    nw_event e;
    EXPECT_EQ(nw_event_at(k.w, 0, &e), NW_ERR_RANGE);  // none yet
    expect_sentence("nw_event_at");

    // A null world, everywhere.
    double d = 0;
    long l = 0;
    int n = 0;
    nw_game g;
    EXPECT_EQ(nw_step(nullptr, 1), NW_ERR_NULL);
    EXPECT_EQ(nw_clock(nullptr, &d, &l), NW_ERR_NULL);
    EXPECT_EQ(nw_curvature(nullptr, &d), NW_ERR_NULL);
    EXPECT_EQ(nw_set_curvature(nullptr, 0), NW_ERR_NULL);
    EXPECT_EQ(nw_control(nullptr, "thrust", 1), NW_ERR_NULL);
    EXPECT_EQ(nw_set_view(nullptr, "gnomonic", 0), NW_ERR_NULL);
    EXPECT_EQ(nw_draw(nullptr, buf.data(), buf.size(), 8, 8, 0, "rgb565"), NW_ERR_NULL);
    EXPECT_EQ(nw_body_count(nullptr, &n), NW_ERR_NULL);
    EXPECT_EQ(nw_body_at(nullptr, 0, &b), NW_ERR_NULL);
    EXPECT_EQ(nw_game_state(nullptr, &g), NW_ERR_NULL);
    EXPECT_EQ(nw_event_count(nullptr, &n), NW_ERR_NULL);
    EXPECT_EQ(nw_event_at(nullptr, 0, &e), NW_ERR_NULL);
    expect_sentence("nw_event_at");
    nw_world_free(nullptr);
}

TEST(CApi, ControlsAndCurvature) {
    World w;
    ASSERT_EQ(nw_world_from_name("kiosk", nullptr, &w.w), NW_OK);
    double K = 9;
    ASSERT_EQ(nw_control(w.w, "hyperbolic", 1), NW_OK);
    ASSERT_EQ(nw_curvature(w.w, &K), NW_OK);
    EXPECT_EQ(K, -1);
    ASSERT_EQ(nw_set_curvature(w.w, 0.25), NW_OK);  // (exact in Q16.16)
    ASSERT_EQ(nw_curvature(w.w, &K), NW_OK);
    EXPECT_EQ(K, 0.25);
    // curvature_up held for one second: K up by the scene's rate, 0.5 a second, within the
    // 60 steps' roundings to Q16.16 (2^-16 each).
    ASSERT_EQ(nw_control(w.w, "curvature_up", 1), NW_OK);
    ASSERT_EQ(nw_step(w.w, 60), NW_OK);
    ASSERT_EQ(nw_control(w.w, "curvature_up", 0), NW_OK);
    ASSERT_EQ(nw_step(w.w, 60), NW_OK);
    ASSERT_EQ(nw_curvature(w.w, &K), NW_OK);
    EXPECT_NEAR(K, 0.75, 60.0 / 65536);
    double t = 0;
    long steps = 0;
    ASSERT_EQ(nw_clock(w.w, &t, &steps), NW_OK);
    EXPECT_EQ(steps, 120);
    EXPECT_NEAR(t, 2.0, 1e-12);
}

// nw_advance: uneven frame times make the same equal steps as nw_step, the remainder carried.
// The reference: the whole steps in the running sum of the seconds given, and the world the
// same as one stepped that many times by nw_step (the same K after curvature_up held).
TEST(CApi, AdvanceStepsUnevenFramesEvenly) {
    World a, b;
    ASSERT_EQ(nw_world_from_name("kiosk", "double", &a.w), NW_OK);
    ASSERT_EQ(nw_world_from_name("kiosk", "double", &b.w), NW_OK);
    ASSERT_EQ(nw_control(a.w, "curvature_up", 1), NW_OK);
    ASSERT_EQ(nw_control(b.w, "curvature_up", 1), NW_OK);
    const double frames[] = {0.010, 0.033, 0.007, 0.050, 0.0166, 0.1, 0.002, 0.021};
    double sum = 0;
    long total = 0;
    for (int round = 0; round < 10; ++round)
        for (double f : frames) {
            long n = -1;
            ASSERT_EQ(nw_advance(a.w, f, &n), NW_OK);
            ASSERT_GE(n, 0);
            total += n, sum += f;
            EXPECT_EQ(total, static_cast<long>(std::floor(sum * 60 + 1e-6))) << "after " << sum << " s";
        }
    ASSERT_EQ(nw_step(b.w, total), NW_OK);
    double ka = 0, kb = 1;
    long sa = 0, sb = 0;
    ASSERT_EQ(nw_curvature(a.w, &ka), NW_OK);
    ASSERT_EQ(nw_curvature(b.w, &kb), NW_OK);
    EXPECT_EQ(ka, kb);
    ASSERT_EQ(nw_clock(a.w, nullptr, &sa), NW_OK);
    ASSERT_EQ(nw_clock(b.w, nullptr, &sb), NW_OK);
    EXPECT_EQ(sa, sb);
    EXPECT_EQ(nw_advance(a.w, -0.1, nullptr), NW_ERR_RANGE);
    EXPECT_EQ(nw_advance(a.w, std::nan(""), nullptr), NW_ERR_RANGE);
    EXPECT_NE(std::string(nw_last_error()).find("nw_advance"), std::string::npos);
    EXPECT_EQ(nw_advance(nullptr, 1, nullptr), NW_ERR_NULL);
}

TEST(CApi, GameEventsAndBodies) {
    World w;
    ASSERT_EQ(nw_world_from_name("asteroids", nullptr, &w.w), NW_OK);
    nw_game g;
    ASSERT_EQ(nw_game_state(w.w, &g), NW_OK);
    EXPECT_EQ(g.on, 1);
    EXPECT_EQ(g.phase, 0);  // "press fire"
    ASSERT_EQ(nw_control(w.w, "fire", 1), NW_OK);
    ASSERT_EQ(nw_control(w.w, "fire", 0), NW_OK);
    ASSERT_EQ(nw_step(w.w, 1), NW_OK);
    int n = 0;
    ASSERT_EQ(nw_event_count(w.w, &n), NW_OK);
    ASSERT_GE(n, 1);
    nw_event e;
    ASSERT_EQ(nw_event_at(w.w, 0, &e), NW_OK);
    EXPECT_EQ(e.kind, NW_EVENT_START);
    ASSERT_EQ(nw_game_state(w.w, &g), NW_OK);
    EXPECT_EQ(g.phase, 1);
    EXPECT_EQ(g.lives, 3);
    EXPECT_EQ(g.level, 1);
    // The ship and the first level's four large asteroids, named as the dump names them.
    ASSERT_EQ(nw_body_count(w.w, &n), NW_OK);
    int ships = 0, asteroids = 0;
    for (int i = 0; i < n; ++i) {
        nw_body b;
        ASSERT_EQ(nw_body_at(w.w, i, &b), NW_OK);
        ships += std::strcmp(b.kind, "ship") == 0;
        if (std::strcmp(b.kind, "asteroid") == 0) {
            ++asteroids;
            EXPECT_EQ(std::string(b.name).rfind("asteroid ", 0), 0u) << b.name;
            EXPECT_EQ(b.vertices, 10);
        }
        EXPECT_TRUE(b.r >= 0 && b.r <= 3.15 && b.theta > -180 && b.theta <= 180) << b.name;
    }
    EXPECT_EQ(ships, 1);
    EXPECT_EQ(asteroids, 4);
}

TEST(CApi, SteppingDrawingAndReadingAllocateNothing) {
    for (const char* scene : {"kiosk", "asteroids", "textured"}) {
        World w;
        ASSERT_EQ(nw_world_from_name(scene, "fixed", &w.w), NW_OK);
        std::vector<uint8_t> buf(320 * 240 * 2);
        ASSERT_EQ(nw_draw(w.w, buf.data(), buf.size(), 320, 240, 0, "rgb565"), NW_OK);  // (the canvas's first draw)
        ASSERT_EQ(nw_control(w.w, "fire", 1), NW_OK);
        test::start_counting();
        for (int f = 0; f < 120; ++f) {
            nw_control(w.w, "thrust", f % 40 < 20);
            nw_step(w.w, 1);
            nw_draw(w.w, buf.data(), buf.size(), 320, 240, 0, "rgb565");
            int n = 0;
            nw_body_count(w.w, &n);
            for (int i = 0; i < n; ++i) {
                nw_body b;
                nw_body_at(w.w, i, &b);
            }
            nw_event_count(w.w, &n);
        }
        EXPECT_EQ(test::stop_counting(), 0) << scene;
    }
}

}  // namespace
