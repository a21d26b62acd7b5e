// A curved-space picture into memory (docs/library.md): a built-in scene run for some frames on
// the fixed-point engine, drawn into a buffer of xrgb8888 pixels, written as a PPM file. The
// pixels are `noneuclid render`'s for the same scene, frames and size (tests/library checks it).
//
//   example_picture SCENE FRAMES WIDTHxHEIGHT OUT.ppm     e.g. kiosk 60 320x240 kiosk.ppm
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fixed/fixed.hpp"
#include "render/draw_world.hpp"
#include "render/palette.hpp"
#include "world/scene.hpp"
#include "world/world.hpp"

int main(int argc, char** argv) {
    using namespace noneuclid;
    world::Scene scene;
    int width = 0, height = 0;
    if (argc != 5 || !world::builtin_scene(argv[1], world::SceneParams{}, scene) ||
        std::sscanf(argv[3], "%dx%d", &width, &height) != 2 || width < 1 || height < 1) {
        std::fprintf(stderr, "usage: example_picture SCENE FRAMES WIDTHxHEIGHT OUT.ppm (SCENE: a built-in scene)\n");
        return 2;
    }
    world::World<fx::fixed> world(scene);  // the device's engine: fixed point and lookup tables
    for (long f = std::atol(argv[2]); f > 0; --f) world.step(1.0 / 60);

    // The caller's memory, described as the kernel describes a framebuffer (render/canvas.hpp).
    std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 4);
    const render::Canvas canvas(pixels.data(), width, height, width * 4, render::PixelFormat::xrgb8888());
    render::DrawOptions options;  // the equidistant projection, the scene's colours
    const render::PaletteFrame frame = render::palette_frame(options.palette);
    options.background = frame.background, options.outside = frame.outside, options.rim = frame.rim;
    render::DrawScratch<fx::fixed> scratch;  // sized once for the world: drawing allocates nothing
    scratch.prepare(world);
    render::draw_world(canvas, world, options, scratch);

    std::FILE* out = std::fopen(argv[4], "wb");
    if (!out) {
        std::perror(argv[4]);
        return 1;
    }
    std::fprintf(out, "P6\n%d %d\n255\n", width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const render::Rgb c = canvas.get(x, y);
            const unsigned char rgb[3] = {c.r, c.g, c.b};
            std::fwrite(rgb, 1, 3, out);
        }
    return std::fclose(out) == 0 ? 0 : 1;
}
