// Lessons played and printed (app/lesson.hpp).
#include "app/lesson.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "app/setup.hpp"
#include "world/quote.hpp"

namespace noneuclid::app {

namespace {

// How long a step without seconds and with nobody watching (the headless display) plays: the
// run's own default for that display, ten seconds.
constexpr long kUnwatchedFrames = 600;

}  // namespace

Options step_options(const files::Lesson& lesson, const Options& base, int i) {
    Options o = base;
    if (o.scene.empty()) o.scene = "kiosk";
    for (int k = 0; k <= i; ++k) {
        const files::LessonStep& s = lesson.steps[k];
        if (!s.scene.empty()) o.scene = s.scene;
        if (!s.projection.empty()) o.projection = parse_projection("the lesson's projection", s.projection);
    }
    const files::LessonStep& s = lesson.steps[i];
    o.has_curvature = s.has_curvature;
    if (s.has_curvature) o.curvature = s.curvature;
    return o;
}

LessonPlayer::LessonPlayer(const files::Lesson& lesson, const Options& base, Display& display, const char* name)
    : lesson_(lesson), base_(base), display_(display), display_name_(name) {
    start(0);
}

void LessonPlayer::start(int i) {
    step_ = i;
    step_options_ = step_options(lesson_, base_, i);
    Options& o = step_options_;
    const files::LessonStep& s = lesson_.steps[i];
    const long seconds_frames = static_cast<long>(s.seconds * 60 + 0.5);
    o.frames = seconds_frames > 0 ? seconds_frames : (display_.realtime() ? 0 : kUnwatchedFrames);
    if (!display_.realtime() && base_.frames > 0) o.frames = std::min(o.frames > 0 ? o.frames : base_.frames, base_.frames);
    // The caption, and where the lesson is: "2/4".
    caption_ = std::to_string(i + 1) + "/" + std::to_string(lesson_.steps.size()) + "  " + s.caption;
    if (s.done.kind != files::LessonDone::fire || s.seconds == 0)
        caption_ += "  (" + files::lesson_done_words(s.done, resolve_language(base_)) + ")";
    if (i + 1 < static_cast<int>(lesson_.steps.size())) o.screenshot.clear();  // the last step's picture only
    o.caption = caption_;
    prepare_run(run_, o);
    compose_run(run_, o, script_, display_, display_name_, nullptr, nullptr);
    fire_seen_ = run_.session->fire_presses();
}

bool LessonPlayer::step_done() const {
    const files::LessonDone& d = lesson_.steps[step_].done;
    const Session& s = *run_.session;
    switch (d.kind) {
        case files::LessonDone::fire: return s.fire_presses() > fire_seen_;
        case files::LessonDone::curvature_above: return s.curvature() > d.value;
        case files::LessonDone::curvature_below: return s.curvature() < d.value;
        case files::LessonDone::score: return static_cast<double>(s.score()) >= d.value;
    }
    return false;
}

bool LessonPlayer::tick() {
    if (over_) return false;
    const bool going = run_.loop->tick();
    if (going && !step_done()) return true;
    const bool closed = display_.closing() || run_.session->quit();
    status_ = run_.loop->finish();
    if (!going && closed) return over_ = true, false;  // the display closed, or quit: the lesson ends
    if (status_ != 0 || step_ + 1 >= static_cast<int>(lesson_.steps.size())) return over_ = true, false;
    start(step_ + 1);  // done, or its time ran out: the next step
    return true;
}

int LessonPlayer::finish() { return status_; }

AttractLessonRun::AttractLessonRun(const files::Lesson& lesson, const Options& o, Display& display, const char* name,
                                   HighScoreTable* scores)
    : lesson_(lesson), o_(o), lesson_o_(o), display_(display), name_(name), scores_(scores) {
    lesson_o_.attract = 1, lesson_o_.screenshot.clear();  // within the lesson the autopilot flies at once
    o_.actions.clear();
    start_run();
}

void AttractLessonRun::start_run() {
    player_.reset();
    Options o = o_;
    prepare_run(run_, o);
    compose_run(run_, o, script_, display_, name_, nullptr, scores_);
    run_.loop->set_sound(sound_);
}

bool AttractLessonRun::tick() {
    // The run's frames (o.frames, 0: until the display closes) count across the scene's runs and
    // the lesson's plays.
    if (o_.frames > 0 && ++frames_ > o_.frames) {
        status_ = player_ ? player_->finish() : run_.loop->finish();
        if (player_ && !o_.screenshot.empty()) {  // (the lesson's steps keep no screenshot: the run's is taken here)
            char where[64];
            std::snprintf(where, sizeof where, "the lesson's step %d, K = %.3f", player_->step() + 1,
                          player_->session().curvature());
            if (write_screenshot(display_, o_.screenshot, where) != 0) status_ = status_ ? status_ : 1;
        }
        return false;
    }
    if (player_) {
        const bool going = player_->tick();
        if (player_->session().presses() > 0) {  // a visitor: the scene for them, from its start
            start_run();
            return true;
        }
        if (!going) {
            if (display_.closing() || player_->session().quit()) return status_ = player_->finish(), false;
            player_ = std::make_unique<LessonPlayer>(lesson_, lesson_o_, display_, name_);  // over: again
        }
        return true;
    }
    if (!run_.loop->tick()) return status_ = run_.loop->finish(), false;
    if (run_.session->attract()) player_ = std::make_unique<LessonPlayer>(lesson_, lesson_o_, display_, name_);
    return true;
}

}  // namespace noneuclid::app
