// Runs an uneven world's frames N times for instruction counting under qemu-user
// (insncount/arm-insncount; docs/performance.md), as frame_probe does for the world of constant K:
//     uneven_probe VIEW SCENE WxH FORMAT N [HOLD]
// VIEW chart|inhabitant, SCENE lens|hills (or any built-in scene with bumps), FORMAT
// rgb565|xrgb8888|rgb888. A frame: the world's step, the view drawn, the copy to a second buffer.
// HOLD: nothing (the metric stays: its caches hold), curvature (curvature down held: the field,
// the fan and the table are rebuilt every frame) or strength (the same through the gain).
// The cost of one frame is (count at N - count at 0) / N: the run at N = 0 does the same set-up
// and the same warm-up frame.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "probe_args.hpp"
#include "render/blit.hpp"
#include "uneven/draw.hpp"

int main(int argc, char** argv) {
    using namespace noneuclid;
    if (argc < 6) {
        std::fprintf(stderr, "usage: uneven_probe chart|inhabitant SCENE WxH FORMAT N [curvature|strength]\n");
        return 2;
    }
    const bool chart = std::strcmp(argv[1], "chart") == 0;
    world::Scene scene;
    if (!world::builtin_scene(argv[2], {}, scene) || scene.bumps.empty()) {
        std::fprintf(stderr, "uneven_probe: no built-in scene with bumps named '%s'.\n", argv[2]);
        return 2;
    }
    int w = 0, h = 0;
    render::PixelFormat f = render::PixelFormat::rgb565();
    if (!probe::canvas_words(argv[3], argv[4], w, h, f)) return 2;
    const long n = std::atol(argv[5]);
    uneven::World wd(scene);
    if (argc > 6 && std::strcmp(argv[6], "curvature") == 0) wd.press(world::Action::curvature_down);
    if (argc > 6 && std::strcmp(argv[6], "strength") == 0) wd.press(world::Action::strength_up);
    uneven::Drawing d;
    d.prepare(wd);
    const std::size_t bytes = static_cast<std::size_t>(w) * h * f.bytes_per_pixel();
    std::vector<uint8_t> back(bytes), front(bytes);
    const render::Canvas c(back.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    const render::Canvas fb(front.data(), w, h, static_cast<std::ptrdiff_t>(w) * f.bytes_per_pixel(), f);
    render::DrawOptions o;
    o.projection = chart ? geo::Projection::stereographic : geo::Projection::azimuthal_equidistant;
    auto frame = [&] {
        wd.step(1.0 / 60);
        d.draw(c, wd, o, true);
        render::copy_canvas(c, fb);
    };
    frame();  // warm-up, in every run
    for (long i = 0; i < n; ++i) frame();
    uint64_t check = 0;
    for (std::size_t i = 0; i < bytes; i += 61) check += front[i];
    std::printf("uneven_probe: %ld frames, check %llu\n", n, static_cast<unsigned long long>(check));
    return 0;
}
