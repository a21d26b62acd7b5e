#include "app/picture.hpp"

#include <algorithm>
#include <cstring>

#include "app/platform.hpp"
#include "app/setup.hpp"

namespace noneuclid::app {

namespace {
// The time-lapse's trail over a picture: every pixel of `trail` not the background.
void lay_trail(const render::Canvas& trail, const render::Canvas& c, uint32_t background) {
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x)
            if (trail.get_word(x, y) != background) c.set_word(x, y, trail.get_word(x, y));
}
PictureResult result(const Session& s, bool stopped, bool refused) {
    PictureResult r;
    r.K = s.curvature(), r.frame = s.frame(), r.stopped = stopped, r.refused = refused;
    return r;
}
}  // namespace

PictureResult render_picture(const Options& o, const world::Scene& scene, const Script* script,
                             const render::Font& font, Picture& out, FrameSink* frames, long every,
                             Progress* progress) {
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(o.width) * o.format.bytes_per_pixel();
    const std::size_t bytes = static_cast<std::size_t>(stride) * static_cast<std::size_t>(o.height);
    out.pixels.assign(bytes, 0);
    out.canvas = render::Canvas(out.pixels.data(), o.width, o.height, stride, o.format);
    Options plain = o;
    plain.attract = 0, plain.threads = 1;
    const kinds::KindChoice kind = world_kind(o, scene);
    const SessionOptions so = session_options(plain, scene, o.legend, kind);
    const std::unique_ptr<Session> s = make_session(kind, scene, so, font, nullptr);
    const uint32_t background = o.format.pack(so.draw.background);

    std::vector<uint8_t> trail;
    render::Canvas layer;
    if (o.timelapse > 0) {
        trail.assign(bytes, 0);
        layer = render::Canvas(trail.data(), o.width, o.height, stride, o.format);
        layer.clear(so.draw.background);
    }
    // The picture as it stands: the world (under the time-lapse, its backdrop and grid, the trail
    // laid over them) and the HUD.
    auto draw = [&] {
        s->draw_world(out.canvas, o.timelapse > 0 ? Layers::backdrop_and_grids : Layers::all);
        if (o.timelapse > 0) lay_trail(layer, out.canvas, background);
        s->draw_hud(out.canvas);
    };
    ScriptPlayer player;
    if (script) player = ScriptPlayer(script->events);
    s->start(player);
    for (long f = 0;; ++f) {
        if (o.timelapse > 0 && o.timelapse_grids > 0 && f % o.timelapse_grids == 0)
            s->draw_world(layer, Layers::grids_tinted, false);
        if (o.timelapse > 0 && f % o.timelapse == 0) s->draw_world(layer, Layers::bodies, false);
        if (frames && f % every == 0) {
            draw();
            if (!frames->frame(out.canvas, f)) return result(*s, false, true);
        }
        if (f == o.frames) break;
        if (platform::stop_signal()) return result(*s, true, false);  // (catch_stop_signals)
        s->advance(player);
        if (progress) progress->at(f + 1, o.frames);
    }
    draw();
    PictureResult r = result(*s, false, false);
    r.readings = s->readings(r.reading, PictureResult::kMaxReadings);
    return r;
}

PictureResult render_figure(const Figure& f, const Options& base, const render::Font& font, Picture& out) {
    constexpr int kGap = 8;
    const int w = base.width, h = base.height, panels = std::max(1, f.panels);
    const int width = panels * w + (panels - 1) * kGap;
    const int bpp = base.format.bytes_per_pixel();
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(width) * bpp;
    out.pixels.assign(static_cast<std::size_t>(stride) * static_cast<std::size_t>(h), 0);
    out.canvas = render::Canvas(out.pixels.data(), width, h, stride, base.format);
    out.canvas.clear({40, 44, 56});  // the gaps
    PictureResult last;
    for (int i = 0; i < panels; ++i) {
        Options o = base;
        o.scene = f.scene, o.frames = f.frames, o.timelapse = f.timelapse, o.timelapse_grids = f.grid_trail, o.aa = f.aa;
        o.hud = base.hud && f.hud;
        o.projection = f.projection, o.params.centre_lat = f.centre_lat, o.params.centre_lon = f.centre_lon;
        if (!f.own_K) o.has_curvature = true, o.curvature = f.K[i];
        char label[64];
        figure_label(f, i, label, sizeof label);
        o.title = label;  // (laid out with the HUD: the disc clears it)
        Picture panel;
        world::Scene scene = load_scene(o);
        if (f.no_ship) std::erase_if(scene.bodies, [](const world::SceneBody& b) { return b.controlled; });
        last = render_picture(o, scene, nullptr, font, panel);
        if (last.stopped) return last;
        for (int y = 0; y < h; ++y)
            std::memcpy(out.canvas.row(y) + static_cast<std::ptrdiff_t>(i) * (w + kGap) * bpp, panel.canvas.row(y),
                        static_cast<std::size_t>(w) * static_cast<std::size_t>(bpp));
    }
    return last;
}

}  // namespace noneuclid::app
