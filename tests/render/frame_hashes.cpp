// frame_hashes: the fixed-point engine's frames, hashed, so that a build for one architecture can
// be compared with another's. The kiosk scene and the asteroids game, each at K = -1, 0 and +1,
// each in two views: equidistant and aliased in RGB565 (the kiosk's), stereographic and
// anti-aliased in XRGB8888; with the HUD, 240 frames while a script holds and taps the controls
// (thrust, turns, fire, curvature up and down, the next preset), through the session and drawing
// code `noneuclid render` runs (app::load_scene, app::session_options, app::make_session).
// Prints one line per checked frame (every 40th):
//
//     <case> frame <n> K <K> canvas <FNV-1a 64 of the canvas bytes> world <FNV-1a 64 of the dump>
//
// where the world's hash is that of the frame's JSON Lines dump (`noneuclid dump`'s line) without
// its "screen" lists: those are the dump's own projection of the points in double precision,
// not the engine's state, and GCC fuses multiply-adds in double code on ARM (-ffp-contract=fast,
// its default) where x86-64 has no FMA to fuse with, so their last bits differ between the
// two. The fixed-point engine is meant to give the same bits on every architecture, so the cross
// builds' output must equal the native build's byte for byte (tests/render/CMakeLists.txt:
// frame_hashes_match_native, frame_hashes_stable). A plain program: no GoogleTest.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/args.hpp"
#include "app/options.hpp"
#include "app/script.hpp"
#include "app/session.hpp"
#include "app/setup.hpp"
#include "render/font.hpp"

using namespace noneuclid;

namespace {

constexpr int kWidth = 256, kHeight = 160;
constexpr long kFrames = 240, kEvery = 40;

// The controls, in world seconds (60 steps a second): fly, turn, start the game and fire, set the
// run's K again (the game's first level sets its own: run() adds the tap), bend K both ways while
// turning, then the next preset K.
constexpr const char* kScript = R"(0.0 press thrust
0.5 press left
0.9 release left
1.0 release thrust
1.1 tap fire
1.3 press fire
1.5 press curvature_up
1.9 press right
2.3 release curvature_up
2.4 release right
2.5 press curvature_down
2.9 release fire
3.3 release curvature_down
3.5 tap preset
3.7 press thrust
)";

// The dump line without its "screen" lists (each `,"screen":[...]` with its nested brackets).
std::string without_screen(const std::string& line) {
    static const std::string key = ",\"screen\":[";
    std::string out;
    std::size_t from = 0;
    for (std::size_t at; (at = line.find(key, from)) != std::string::npos;) {
        out.append(line, from, at - from);
        std::size_t i = at + key.size();
        for (int depth = 1; i < line.size() && depth > 0; ++i) depth += line[i] == '[' ? 1 : (line[i] == ']' ? -1 : 0);
        from = i;
    }
    return out.append(line, from, std::string::npos);
}

// FNV-1a, 64 bits.
uint64_t fnv1a(const uint8_t* p, std::size_t n, uint64_t h = 0xcbf29ce484222325ull) {
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

struct Case {
    const char* scene;
    double K;
    bool stereographic_aa;  // else equidistant, aliased
};

// Runs one case and prints its checked frames.
void run(const Case& c) {
    const char* const k_control = c.K < 0 ? "hyperbolic" : (c.K > 0 ? "spherical" : "flat");
    const std::string text = std::string(kScript) + "1.2 tap " + k_control + "\n";
    app::Script script;
    app::ScriptError error;
    if (!app::parse_script(text, "frame_hashes script", script, error)) app::usage_error(error.to_string());

    app::Options o = app::defaults(app::Command::render);
    o.scene = c.scene, o.has_curvature = true, o.curvature = c.K;
    o.engine = world::engine_named("fixed"), o.hud = true, o.width = kWidth, o.height = kHeight;
    o.aa = c.stereographic_aa;
    o.projection = o.aa ? geo::Projection::stereographic : geo::Projection::azimuthal_equidistant;
    o.format = o.aa ? render::PixelFormat::xrgb8888() : render::PixelFormat::rgb565();
    const world::Scene scene = app::load_scene(o);
    const app::SessionOptions so = app::session_options(o, scene, "buttons", app::world_kind(o, scene));
    const std::unique_ptr<app::Session> s =
        app::make_session(app::world_kind(o, scene), scene, so, render::builtin_font(), nullptr);

    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(kWidth) * o.format.bytes_per_pixel();
    std::vector<uint8_t> pixels(static_cast<std::size_t>(stride) * kHeight);
    const render::Canvas canvas(pixels.data(), kWidth, kHeight, stride, o.format);
    char name[96];
    std::snprintf(name, sizeof name, "%s/K%+g/%s/%s", c.scene, c.K, geo::projection_name(o.projection),
                  o.aa ? "aa" : "aliased");

    app::ScriptPlayer player(script.events);
    std::string line;
    for (long f = 1; f <= kFrames; ++f) {
        s->play_due(player);
        s->step();
        s->draw(canvas);
        if (f % kEvery != 0) continue;
        s->dump(kWidth, kHeight, line);
        const std::string state = without_screen(line);
        const uint64_t world = fnv1a(reinterpret_cast<const uint8_t*>(state.data()), state.size());
        std::printf("%s frame %ld K %.9g canvas %016llx world %016llx\n", name, s->frame(), s->curvature(),
                    static_cast<unsigned long long>(fnv1a(pixels.data(), pixels.size())),
                    static_cast<unsigned long long>(world));
    }
}

}  // namespace

int main() {
    try {
        for (const char* scene : {"kiosk", "asteroids"})
            for (double K : {-1.0, 0.0, 1.0})
                for (bool stereographic_aa : {false, true}) run({scene, K, stereographic_aa});
    } catch (const app::UsageError& e) {
        std::fprintf(stderr, "frame_hashes: %s\n", e.message.c_str());
        return 1;
    }
    return 0;
}
