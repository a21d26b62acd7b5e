// One running world and how it is shown: the world (any kind, kinds/kind.hpp, on its engine), the view (projection, HUD),
// the controls in (live buttons and keys, scripted events, the attract-mode autopilot), one
// step of world time and one drawn frame out. Every display's frame loop (app/frame_loop.hpp)
// and the batch commands (render, dump) run a Session, so a key does the same thing
// everywhere and a recording replays bit for bit. Allocates nothing per frame.
//
// Order within a frame (advance): the controls due (queued live input, then the autopilot's),
// each reported to the recorder with the world time, then one step, then the scripted events
// due at the new time (ScriptPlayer), then the picture.
#pragma once

#include <memory>
#include <string>

#include "app/autopilot.hpp"
#include "kinds/kinds.hpp"
#include "kinds/step.hpp"
#include "app/script.hpp"
#include "app/sound.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"
#include "render/layout.hpp"
#include "lang/lang.hpp"
#include "render/font.hpp"
#include "files/dump.hpp"
#include "world/instruments.hpp"
#include "world/scene.hpp"

namespace noneuclid::app {

class Recorder;

struct SessionOptions {
    render::DrawOptions draw;
    bool hud = true;
    bool large_hud = false;       // the HUD's text twice as large
    int hud_scale = 0;            // the HUD's text size (render::HudInfo::scale; 0: by the canvas)
    std::string caption;          // a lesson step's caption on the HUD (app/lesson.hpp)
    std::string title;            // a figure's label, top-left, with the HUD or without
    bool one_button = false;      // fire alone plays (app/one_button.hpp)
    bool show_fps = false;        // the frame rate on the HUD (wall-clock: never in a replay)
    std::string scene_name;
    std::string legend;           // the HUD's controls line (in `language`)
    lang::Language language = lang::Language::en;  // of the HUD's words
    AttractOptions attract{0, 40, 0.25};  // idle_seconds 0: off
    int threads = 1;              // drawing threads (a pool started once); the same pixels
    double dt = kinds::kStepSeconds;  // world seconds per step
    long best = 0;                // a game's high score before this session (its HUD shows it)
    bool muted = false;           // the sound starts muted (the mute control turns it on and off)
    bool panels = true;           // the instruments' readings beside the disc (a worksheet's picture: none)
};

// Told of each game that ends (the high-score table, app/high_scores.hpp).
class GameOverSink {
public:
    virtual void game_over(long score, int level) = 0;

protected:
    ~GameOverSink() = default;
};

// What Session::draw_world draws: everything, or a time-lapse's layers (grids_tinted: the grids
// in a colour of K, from blue at -1 to red at +1).
enum class Layers { all, bodies, grids_tinted, backdrop_and_grids };

class Session {
public:
    virtual ~Session() = default;

    // Live input (a display's buttons and keys): applied at the start of the next step, so a
    // recording holds exactly what the frames saw. quit acts at once.
    virtual void queue(world::InputEvent e) = 0;
    // Scripted input at its time (an actions file): applied now.
    virtual void play(const ScriptEvent& e) = 0;
    // A mark of the live instrument where a canvas of width x height shows the pixel (x, y) (a
    // tap on the web page's canvas), played as a mark event; false where it shows no point of
    // the world.
    virtual bool mark_at(double x, double y, int width, int height) = 0;
    // Plays every event of `player` due by the world time now.
    void play_due(ScriptPlayer& player) {
        while (const ScriptEvent* e = player.next_due(time())) play(*e);
    }
    // The one order of a run (kinds/step.hpp, the firmware's too), for the frame loop, render
    // and dump alike: play_due before the first step (start), then each frame one step and the
    // events due at the new time (advance).
    void start(ScriptPlayer& player) {
        kinds::start_run([&] { play_due(player); });
    }
    void advance(ScriptPlayer& player) {
        kinds::advance_run([&] { step(); }, [&] { play_due(player); });
    }
    // The queued input, the autopilot, one step of dt.
    virtual void step() = 0;
    // The world (no HUD) in `layers`; with backdrop false, over what the canvas holds.
    virtual void draw_world(const render::Canvas& c, Layers layers = Layers::all, bool backdrop = true) = 0;
    // The HUD, if it is on (and the title and the instruments' panels, with it or without).
    virtual void draw_hud(const render::Canvas& c) = 0;
    // Where draw_hud puts its parts on a canvas of this size, and the disc draw_world leaves
    // them (render/layout.hpp).
    virtual render::HudLayout layout(int width, int height) const = 0;
    void draw(const render::Canvas& c) {
        draw_world(c);
        draw_hud(c);
    }
    // One JSON Lines frame of the world (`noneuclid dump`), for a canvas of this size.
    virtual void dump(int width, int height, std::string& line) const = 0;

    virtual double time() const = 0;       // world seconds so far
    virtual long frame() const = 0;        // steps taken
    virtual double curvature() const = 0;  // K now
    virtual long score() const = 0;        // the game's score now (0 without the game)
    virtual long fire_presses() const = 0; // presses of fire so far (a lesson's "press fire to go on")
    virtual long presses() const = 0;      // presses of any button or key so far (not the autopilot's)
    virtual bool attract() const = 0;      // attract mode's autopilot flies now
    // The readings of the instruments that are on (at most `max`, in the world's order): their
    // count.
    virtual int readings(world::GaugeReading* out, int max) const = 0;
    // What the last step asks of the sound (app/sound.hpp): the game's cues that began in it (a
    // shot fired, a hit, a crash, a new level, game over), thrust held, the mute. Attract mode
    // is silent: an idle kiosk does not play to the room.
    virtual SoundFrame sound() const = 0;
    virtual bool quit() const = 0;         // a quit control came
    virtual void set_fps(double fps) = 0;  // shown by the HUD with show_fps
    virtual const SessionOptions& options() const = 0;  // as now (P and H change them)
};

// A session of `scene` as the kind of world chosen for it (kinds/kinds.hpp, choose_kind), its
// drawing threads started. `font` (the HUD's), `recorder` and `scores` (both may be null) must
// outlive it.
std::unique_ptr<Session> make_session(kinds::KindChoice kind, const world::Scene& scene, const SessionOptions& options,
                                      const render::Font& font, Recorder* recorder, GameOverSink* scores = nullptr);

}  // namespace noneuclid::app
