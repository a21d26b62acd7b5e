// A lesson played (files/lesson_file.hpp, docs/lessons.md): its steps one after another on one
// display, each a run of its scene (app/run.hpp) with the step's caption on the HUD, ended by
// what counts as done, by its seconds, or by the display closing. (Its worksheet: app/worksheet.hpp.)
#pragma once

#include <memory>
#include <string>

#include "app/run.hpp"
#include "files/lesson_file.hpp"

namespace noneuclid::app {

class LessonPlayer {
public:
    // `base`: the run's options (display, size, palette...); each step's scene, K and projection
    // go over them. Everything passed must outlive the player.
    LessonPlayer(const files::Lesson& lesson, const Options& base, Display& display, const char* display_name);

    // One frame: false once the lesson is over or the display closed (or quit).
    bool tick();
    // The exit status at the end (the last step's loop's).
    int finish();

    int step() const { return step_; }           // the step playing, from 0
    const Session& session() const { return *run_.session; }
    Session& session() { return *run_.session; }
    const world::Scene& scene() const { return run_.scene; }  // the step's

private:
    void start(int step);
    bool step_done() const;

    const files::Lesson& lesson_;
    Options base_, step_options_;
    Display& display_;
    const char* display_name_;
    Script script_;  // (none: a lesson has no actions file)
    LiveRun run_;
    int step_ = -1;
    long fire_seen_ = 0;
    bool over_ = false;
    int status_ = 0;
    std::string caption_;
};

// A run whose attract mode plays a lesson (the kiosk's `[attract] lesson`, --attract-lesson):
// the scene's run until its attract mode begins (no button for o.attract seconds), then the
// lesson, over and over, attract mode flying within each of its steps (so that a step waiting
// for K ends as the autopilot sweeps it); a button pressed during the lesson gives the visitor a
// new run of the scene. Not recorded (each run is new).
class AttractLessonRun {
public:
    AttractLessonRun(const files::Lesson& lesson, const Options& o, Display& display, const char* display_name,
                     HighScoreTable* scores);
    bool tick();  // one frame: false when the run ends (the display closed, quit)
    int finish() { return status_; }
    bool in_lesson() const { return player_ != nullptr; }
    const Session& session() const { return player_ ? player_->session() : *run_.session; }
    // The visitors' runs' sound (the lesson, attract mode, is silent); it must outlive this.
    void set_sound(SoundOut* sound) {
        sound_ = sound;
        if (!player_) run_.loop->set_sound(sound);
    }

private:
    void start_run();

    const files::Lesson& lesson_;
    Options o_, lesson_o_;
    Display& display_;
    const char* name_;
    HighScoreTable* scores_;
    Script script_;
    LiveRun run_;
    std::unique_ptr<LessonPlayer> player_;
    SoundOut* sound_ = nullptr;
    long frames_ = 0;
    int status_ = 0;
};

// The options of step `i`: the base's, then every earlier step's scene and projection carried
// on, then this step's.
Options step_options(const files::Lesson& lesson, const Options& base, int i);

// `noneuclid lesson NAME [run's options]`: argv from `first` on are run's options; the display
// chosen as run chooses it (app/cmd_run.cpp). Returns the exit status.
int play_lesson(const files::Lesson& lesson, int argc, char** argv, int first);
// The lesson `name` names: a built-in's, else a file's (a UsageError, one sentence, if neither).
files::Lesson load_lesson(const std::string& name, lang::Language language);

}  // namespace noneuclid::app
