#include "app/picture.hpp"

#include "app/platform.hpp"
#include "app/setup.hpp"

namespace noneuclid::app {

PictureResult render_picture(const Options& o, const world::Scene& scene, const Script* script,
                             const render::Font& font, Picture& out) {
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(o.width) * o.format.bytes_per_pixel();
    const std::size_t bytes = static_cast<std::size_t>(stride) * static_cast<std::size_t>(o.height);
    out.pixels.assign(bytes, 0);
    out.canvas = render::Canvas(out.pixels.data(), o.width, o.height, stride, o.format);
    Options plain = o;
    plain.attract = 0, plain.threads = 1;
    const SessionOptions so = session_options(plain, scene, o.legend);
    const std::unique_ptr<Session> s = make_session(o.engine, scene, so, font, nullptr);

    std::vector<uint8_t> trail;
    render::Canvas layer;
    if (o.timelapse > 0) {
        trail.assign(bytes, 0);
        layer = render::Canvas(trail.data(), o.width, o.height, stride, o.format);
        layer.clear(so.draw.background);
    }
    ScriptPlayer player;
    if (script) player = ScriptPlayer(script->events);
    s->play_due(player);
    for (long f = 0;; ++f) {
        if (o.timelapse > 0 && f % o.timelapse == 0) s->draw_world(layer, Layers::bodies, false);
        if (f == o.frames) break;
        if (platform::stop_signal()) return {s->curvature(), s->frame(), true};  // (catch_stop_signals)
        s->step();
        s->play_due(player);
    }
    s->draw_world(out.canvas, o.timelapse > 0 ? Layers::backdrop_and_grids : Layers::all);
    if (o.timelapse > 0) {  // the bodies' trail over the final backdrop and grid
        const uint32_t bg = o.format.pack(so.draw.background);
        for (int y = 0; y < o.height; ++y)
            for (int x = 0; x < o.width; ++x)
                if (layer.get_word(x, y) != bg) out.canvas.set_word(x, y, layer.get_word(x, y));
    }
    s->draw_hud(out.canvas);
    return {s->curvature(), s->frame(), false};
}

}  // namespace noneuclid::app
