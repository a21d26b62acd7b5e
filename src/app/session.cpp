// A Session for each kind of world on each of its engines (kinds/kinds.hpp; see session.hpp).
#include "app/session.hpp"

#include <cmath>
#include <cstdio>

#include "app/one_button.hpp"
#include "app/recorder.hpp"
#include "geometry/local_frame.hpp"
#include "kinds/kinds.hpp"
#include "render/hud.hpp"
#include "render/layout.hpp"
#include "render/measure_panel.hpp"
#include "render/play.hpp"
#include "render/worker_pool.hpp"

namespace noneuclid::app {
namespace {

// The colour of a time-lapse's grid at K: blue at K = -1, grey at 0, red at +1.
render::Rgb curvature_tint(double K) {
    const double k = K < -1 ? -1 : (K > 1 ? 1 : K);
    const double from[3] = {150, 160, 180}, to[3] = {k < 0 ? 60. : 240., k < 0 ? 140. : 70., k < 0 ? 255. : 110.};
    const double a = k < 0 ? -k : k;
    auto mix = [&](int i) { return static_cast<uint8_t>(from[i] + (to[i] - from[i]) * a + 0.5); };
    return {mix(0), mix(1), mix(2)};
}

template <kinds::WorldKind WK>
class KindSession final : public Session {
public:
    using T = typename WK::World::scalar;

    KindSession(const world::Scene& scene, const SessionOptions& o, const render::Font& font, Recorder* recorder,
                  GameOverSink* scores)
        : kind_(scene),
          options_(o),
          font_(font),
          recorder_(recorder),
          scores_(scores),
          best_{o.best},
          pool_(o.threads),
          autopilot_(o.attract, scene.curvature_rate),
          dt_(o.dt) {
        sound_.muted = o.muted;
        kind_.prepare(pool_);
    }

    void queue(world::InputEvent e) override {
        if (e.control == world::Action::quit) {
            if (e.pressed) quit_ = true;
            return;
        }
        if (queued_ == kQueue) flush();  // a flood of input: the same world time either way
        queue_[queued_++] = e;
    }

    void play(const ScriptEvent& e) override {
        switch (e.kind) {
            case ScriptEvent::attract_on:
            case ScriptEvent::attract_off:
                replayed_attract_ = e.kind == ScriptEvent::attract_on;
                record(e.kind);
                return;
            case ScriptEvent::press: control({e.control, true}); return;
            case ScriptEvent::release: control({e.control, false}); return;
            case ScriptEvent::tap:
                control({e.control, true});
                control({e.control, false});
                return;
            case ScriptEvent::mark:
                world_.place_mark({T(e.r), geo::wrap_pi(T(e.theta_deg * (3.14159265358979323846 / 180)))});
                if (recorder_) recorder_->mark(world_.time, e.r, e.theta_deg);
                return;
        }
    }

    bool mark_at(double x, double y, int width, int height) override {
        if (!WK::marks_in(options_.draw.projection)) return false;
        const double K = static_cast<double>(world_.K), R = static_cast<double>(world_.R);
        const geo::Projection p = options_.draw.projection;
        const geo::ScreenMap<double> m = geo::ScreenMap<double>::of(width, height, K, R, p, layout(width, height).disc);
        const geo::Unprojected<double> u = geo::unproject(K, (x - m.cx) / m.scale, (m.cy - y) / m.scale, p);
        if (!u.valid) return false;
        const geo::Polar<double> at = geo::to_polar(K, u.p);
        if (!(at.r <= R) || !std::isfinite(at.theta)) return false;
        ScriptEvent e;
        e.time = world_.time, e.kind = ScriptEvent::mark, e.r = at.r, e.theta_deg = at.theta * (180 / 3.14159265358979323846);
        play(e);
        return true;
    }

    void step() override {
        flush();
        world::InputEvent ap[8];
        if (user_held_any()) autopilot_.interrupt(world_.time, ap);  // a held button is not idle
        const bool was = autopilot_.active();
        const int n = autopilot_.frame(world_.time, pilot_view(), ap);
        if (!was && autopilot_.active()) record(ScriptEvent::attract_on);
        for (int i = 0; i < n; ++i) apply(ap[i]);
        if (options_.one_button && !autopilot_.active()) {
            world::InputEvent ob[2];
            const int k = one_button_.step(world_.time, world_.held(world::Action::left), ob);
            for (int i = 0; i < k; ++i) apply(ob[i]);
        }
        const world::GamePhase before = world_.game().phase;
        const double next_shot = world_.game().next_shot();
        world_.step(dt_);
        game_events(before);
        sound_cues(next_shot);
    }

    void draw_world(const render::Canvas& c, Layers layers, bool backdrop) override {
        render::DrawOptions o = options_.draw;
        if (layers == Layers::bodies) o.grids = false;
        if (layers == Layers::backdrop_and_grids) o.bodies = false;
        if (layers == Layers::grids_tinted)
            o.bodies = false, o.tint_grids = true, o.grid_tint = curvature_tint(static_cast<double>(world_.K));
        o.disc = layout(c.width(), c.height()).disc;
        kind_.draw(c, o, backdrop, pool_);
    }

    void draw_hud(const render::Canvas& c) override {
        char note[120];
        const render::HudInfo info = hud_info(note, sizeof note);
        const render::HudLayout l = render::layout_hud(c.width(), c.height(), font_, info);
        // The instruments' readings, with the HUD or without: they are the instruments' faces.
        int side = 0;
        for (const auto& g : world_.gauges())
            if (g.on() && side < info.panels)
                render::draw_measure_panel(c, font_, render::measure_panel(g.reading(), options_.language), l.panel[side++],
                                           l.panel_scale);
        const render::PaletteFrame colours = render::palette_frame(options_.draw.palette);
        render::draw_hud(c, font_, info, l, colours.text, colours.dim);
    }

    render::HudLayout layout(int width, int height) const override {
        char note[120];
        return render::layout_hud(width, height, font_, hud_info(note, sizeof note));
    }

    void dump(int width, int height, std::string& line) const override {
        files::DumpOptions o;
        o.width = width, o.height = height, o.projection = options_.draw.projection;
        kind_.dump(o, line);
    }

    double time() const override { return world_.time; }
    long frame() const override { return world_.frame; }
    double curvature() const override { return static_cast<double>(world_.K); }
    long score() const override { return world_.game().score; }
    long fire_presses() const override { return fire_presses_; }
    int readings(world::GaugeReading* out, int max) const override {
        int n = 0;
        for (const auto& g : world_.gauges())
            if (g.on() && n < max) out[n++] = g.reading();
        return n;
    }
    long presses() const override { return presses_; }
    bool attract() const override { return autopilot_.active(); }
    SoundFrame sound() const override { return sound_; }
    bool quit() const override { return quit_; }
    void set_fps(double fps) override { fps_ = fps; }
    const SessionOptions& options() const override { return options_; }

private:
    static constexpr int kQueue = 64;

    // What the HUD shows now (`note`: room for the kind's note line).
    render::HudInfo hud_info(char* note, std::size_t size) const {
        using lang::Text;
        render::HudInfo info;
        info.on = options_.hud;
        info.title = options_.title.c_str();
        for (const auto& g : world_.gauges())
            if (g.on() && options_.panels && info.panels < 2) ++info.panels;
        info.K = static_cast<double>(world_.K);
        info.fps = options_.show_fps ? fps_ : 0;
        info.scene = options_.scene_name.c_str();
        info.projection = WK::view_words(options_.draw.projection, options_.language);
        const Text attract_words = world_.game().on() ? Text::legend_attract_game : Text::legend_attract;
        const bool attract = autopilot_.active() || replayed_attract_;
        info.controls = attract ? lang::text(attract_words, options_.language) : options_.legend.c_str();
        info.other_legend = attract ? options_.legend.c_str() : lang::text(attract_words, options_.language);
        info.game = render::hud_game(world_, best_);
        if (kind_.note(note, size, options_.language)) info.note = note;
        info.large = options_.large_hud;
        info.scale = options_.hud_scale;
        info.caption = options_.caption.c_str();
        info.language = options_.language;
        return info;
    }
    OneButton one_button_;
    long fire_presses_ = 0, presses_ = 0;

    void flush() {
        for (int i = 0; i < queued_; ++i) control(queue_[i]);
        queued_ = 0;
    }
    // A button, key or scripted event: it ends attract mode (the autopilot's held controls are
    // released and the world reset first), then takes effect.
    void control(world::InputEvent e) {
        world::InputEvent ap[8];
        if (e.pressed || user_held_any()) {
            const int n = autopilot_.interrupt(world_.time, ap);
            if (n > 0) record(ScriptEvent::attract_off);
            for (int i = 0; i < n; ++i) apply(ap[i]);
        }
        user_held_[static_cast<int>(e.control)] = e.pressed;
        if (e.control == world::Action::fire && e.pressed) ++fire_presses_;
        if (e.pressed) ++presses_;
        if (options_.one_button && e.control == world::Action::fire) {  // (app/one_button.hpp)
            world::InputEvent out[2];
            const int n = one_button_.fire(e.pressed, world_.time, world_.game().on(), out);
            for (int i = 0; i < n; ++i) apply(out[i]);
            return;
        }
        apply(e);
    }
    // Takes effect and is recorded: a world action when it changes something (a press of what
    // is held is not), a view control on its press.
    void apply(world::InputEvent e) {
        const render::Applied done = render::apply_control(world_, e.control, e.pressed);
        if (done == render::Applied::pressed || done == render::Applied::released)
            record(e.pressed ? ScriptEvent::press : ScriptEvent::release, e.control);
        if (done != render::Applied::not_action || !e.pressed) return;
        switch (e.control) {
            case world::Action::projection:  // the kind's next view
                options_.draw.projection = WK::next_view(options_.draw.projection);
                record(ScriptEvent::tap, e.control);
                break;
            case world::Action::hud:
                options_.hud = !options_.hud;
                record(ScriptEvent::tap, e.control);
                break;
            case world::Action::quit: quit_ = true; break;
            case world::Action::mute:
                sound_.muted = !sound_.muted;
                record(ScriptEvent::tap, e.control);
                break;
            default: break;
        }
    }
    void record(ScriptEvent::Kind kind, world::Action c = world::Action::thrust) {
        if (recorder_) recorder_->event(world_.time, kind, c);
    }
    bool user_held_any() const {
        for (bool h : user_held_)
            if (h) return true;
        return false;
    }
    PilotView pilot_view() const {
        PilotView v;
        v.K = static_cast<double>(world_.K);
        WK::ship_speed(world_, v.ship_speed);
        v.measuring = world_.measuring(), v.instrument = WK::has_instrument(world_);
        const auto& g = world_.game();
        v.game = g.on();
        if (v.game) {
            v.ready = g.phase == world::GamePhase::ready;
            v.target = WK::aim(world_, v.aim, v.distance);
            v.range = world_.scene().game.bullet_range;
        }
        return v;
    }
    // After a step: a game that ended goes to the high-score table and may beat the best; when
    // its game-over screen is done, attract mode (if on) plays the next one.
    void game_events(world::GamePhase before) {
        const auto& g = world_.game();
        for (int i = 0; i < g.event_count(); ++i) {
            const world::GameEvent& e = g.events()[i];
            best_.take(e);
            if (e.kind == world::GameEvent::over && scores_) scores_->game_over(e.value, g.level);
        }
        if (before == world::GamePhase::over && g.phase == world::GamePhase::ready) autopilot_.engage();
    }
    // After a step: its cues. A shot moved the game's next shot on (Game::shoot); the game's
    // events name the rest.
    void sound_cues(double next_shot) {
        const auto& g = world_.game();
        sound_.cues = 0;
        sound_.thrust = false;
        if (autopilot_.active() || replayed_attract_) return;
        bool started = false;  // (a game's start moves the next shot on too, and fires none)
        for (int i = 0; i < g.event_count(); ++i) switch (g.events()[i].kind) {
                case world::GameEvent::hit: sound_.add(Cue::hit); break;
                case world::GameEvent::crash: sound_.add(Cue::crash); break;
                case world::GameEvent::level: sound_.add(Cue::level); break;
                case world::GameEvent::over: sound_.add(Cue::over); break;
                case world::GameEvent::start: started = true; break;
            }
        if (g.next_shot() > next_shot && !started) sound_.add(Cue::fire);
        // The hum is the ship's engine: none while there is no ship (the "press fire" screen).
        double speed = 0;
        if (WK::ship_speed(world_, speed)) sound_.thrust = world_.held(world::Action::thrust);
    }

    WK kind_;
    typename WK::World& world_ = kind_.world;
    SessionOptions options_;
    const render::Font& font_;
    Recorder* recorder_;
    GameOverSink* scores_;
    render::BestScore best_;
    render::WorkerPool pool_;
    Autopilot autopilot_;
    double dt_;  // world seconds a step: the clock (World::step)
    world::InputEvent queue_[kQueue];
    int queued_ = 0;
    bool user_held_[world::kActionCount] = {};
    bool quit_ = false, replayed_attract_ = false;
    SoundFrame sound_;
    double fps_ = 0;
};

}  // namespace

std::unique_ptr<Session> make_session(kinds::KindChoice kind, const world::Scene& scene, const SessionOptions& options,
                                      const render::Font& font, Recorder* recorder, GameOverSink* scores) {
    return kinds::with_kind(kind, [&]<class WK>(std::type_identity<WK>) -> std::unique_ptr<Session> {
        return std::make_unique<KindSession<WK>>(scene, options, font, recorder, scores);
    });
}

}  // namespace noneuclid::app
