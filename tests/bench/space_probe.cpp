// Runs the three-dimensional world's frames N times for instruction counting under qemu-user
// (insncount/arm-insncount; docs/performance.md), as frame_probe does for the world of constant K:
//     space_probe VIEW SCENE WxH FORMAT N [K|sweep [fixed|double]]
// VIEW inhabitant|map, SCENE space|8-cell|order-5-cubic, FORMAT rgb565|xrgb8888|rgb888; K a
// curvature to start at (the scene's: -), or sweep; the engine (fixed, the device's, unless told) (curvature down held, then up: K changes every frame, so the
// honeycomb is rebuilt every frame). A frame: the world's step, the view drawn, the copy to a
// second buffer. The cost of one frame is (count at N - count at 0) / N: the run at N = 0 does
// the same set-up and the same warm-up frame.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "fixed/fixed.hpp"
#include "probe_args.hpp"
#include "render/blit.hpp"
#include "space/scene_draw.hpp"
#include "world/scene.hpp"

namespace {
using namespace noneuclid;

template <class T>
int run(const world::Scene& scene, bool map, bool sweep, int w, int h, render::PixelFormat f, long n) {
    space::SceneWorldOf<T> world(scene);
    const std::size_t bytes = static_cast<std::size_t>(w) * h * f.bytes_per_pixel();
    std::vector<uint8_t> back(bytes), front(bytes);
    const render::Canvas c(back.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    const render::Canvas fb(front.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    render::DrawOptions o;
    render::BackdropRows rows;  // (kept from frame to frame, as the kind keeps them)
    rows.reserve(h);
    long frames = 0;
    auto frame = [&] {
        if (sweep) {  // (down for a second, up for a second: K always moving, never clamped long)
            const bool down = (frames / 60) % 2 == 0;
            world.release(down ? world::Action::curvature_up : world::Action::curvature_down);
            world.press(down ? world::Action::curvature_down : world::Action::curvature_up);
        }
        world.step(1.0 / 60);
        space::draw_space(c, world, o, map, true, &rows);
        render::copy_canvas(c, fb);
        ++frames;
    };
    frame();  // warm-up, in every run
    for (long i = 0; i < n; ++i) frame();
    uint64_t check = 0;
    for (std::size_t i = 0; i < bytes; i += 61) check += front[i];
    std::printf("space_probe: %ld frames, K = %.3f, check %llu\n", n, static_cast<double>(world.K), static_cast<unsigned long long>(check));
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr, "usage: space_probe inhabitant|map SCENE WxH FORMAT N [K|sweep|- [fixed|double]]\n");
        return 2;
    }
    const bool map = std::strcmp(argv[1], "map") == 0;
    world::Scene scene;
    if (!world::builtin_scene(argv[2], {}, scene) || !scene.space) {
        std::fprintf(stderr, "space_probe: no built-in three-dimensional scene named '%s'.\n", argv[2]);
        return 2;
    }
    int w = 0, h = 0;
    render::PixelFormat f = render::PixelFormat::rgb565();
    if (!probe::canvas_words(argv[3], argv[4], w, h, f)) return 2;
    const long n = std::atol(argv[5]);
    const bool sweep = argc > 6 && std::strcmp(argv[6], "sweep") == 0;
    if (argc > 6 && !sweep && std::strcmp(argv[6], "-") != 0) scene.curvature = std::atof(argv[6]);
    if (argc > 7 && std::strcmp(argv[7], "double") == 0) return run<double>(scene, map, sweep, w, h, f, n);
    return run<fx::fixed>(scene, map, sweep, w, h, f, n);
}
