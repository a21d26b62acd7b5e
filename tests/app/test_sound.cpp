// The game's sound (app/sound.hpp, docs/sound.md): each cue's length, level and pitch measured
// in the samples the synthesiser renders, against the documented figures (and, for a glide,
// the cycles an exponential glide has, integrated by hand); silence when muted; the same cues,
// the same samples. Then the session's cues against the game as `dump` reports it: a fire cue
// in each step a new bullet appears, a hit cue in each step with a hit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/options.hpp"
#include "app/setup.hpp"
#include "app/sound.hpp"
#include "render/font.hpp"

namespace {

using namespace noneuclid;
using app::Cue;

constexpr int kRate = 44100;

std::vector<int16_t> render_cue(Cue c, double seconds) {
    app::Synth s(kRate);
    s.play(c);
    std::vector<int16_t> out(static_cast<std::size_t>(seconds * kRate));
    s.render(out.data(), static_cast<int>(out.size()));
    return out;
}
long last_nonzero(const std::vector<int16_t>& v) {
    for (long i = static_cast<long>(v.size()) - 1; i >= 0; --i)
        if (v[static_cast<std::size_t>(i)] != 0) return i;
    return -1;
}
int peak(const std::vector<int16_t>& v, std::size_t from = 0, std::size_t to = SIZE_MAX) {
    int p = 0;
    for (std::size_t i = from; i < v.size() && i < to; ++i) p = std::max(p, std::abs(static_cast<int>(v[i])));
    return p;
}
// Cycles between samples a and b, from the sign changes (two a cycle).
double cycles(const std::vector<int16_t>& v, std::size_t a, std::size_t b) {
    int changes = 0, sign = 0;
    for (std::size_t i = a; i < b; ++i) {
        const int s = v[i] > 0 ? 1 : (v[i] < 0 ? -1 : 0);
        if (s != 0 && sign != 0 && s != sign) ++changes;
        if (s != 0) sign = s;
    }
    return changes / 2.0;
}

// docs/sound.md's table, by hand: the synthesiser's own table must say the same, and the tests
// below measure the samples against it.
struct Documented {
    Cue cue;
    app::CueSound::Wave wave;
    double start_hz, end_hz, seconds, level, attack_s, release_s;
};
constexpr Documented kDocumented[] = {
    {Cue::fire, app::CueSound::square, 880, 880, 0.08, 0.25, 0.002, 0.02},
    {Cue::hit, app::CueSound::noise, 3000, 3000, 0.15, 0.40, 0.002, 0.10},
    {Cue::crash, app::CueSound::noise, 800, 800, 0.60, 0.60, 0.005, 0.50},
    {Cue::level, app::CueSound::sine, 440, 880, 0.40, 0.35, 0.010, 0.10},
    {Cue::over, app::CueSound::sine, 440, 110, 1.00, 0.40, 0.010, 0.30},
    {Cue::thrust, app::CueSound::noise, 150, 150, 0, 0.20, 0.020, 0.020},
};

TEST(Sound, TheCuesAreAsDocumented) {
    for (const Documented& d : kDocumented) {
        const app::CueSound& s = app::cue_sound(d.cue);
        EXPECT_EQ(s.wave, d.wave) << app::cue_name(d.cue);
        EXPECT_EQ(s.start_hz, d.start_hz) << app::cue_name(d.cue);
        EXPECT_EQ(s.end_hz, d.end_hz) << app::cue_name(d.cue);
        EXPECT_EQ(s.seconds, d.seconds) << app::cue_name(d.cue);
        EXPECT_EQ(s.level, d.level) << app::cue_name(d.cue);
        EXPECT_EQ(s.attack_s, d.attack_s) << app::cue_name(d.cue);
        EXPECT_EQ(s.release_s, d.release_s) << app::cue_name(d.cue);
    }
}

TEST(Sound, EachCueLastsItsDocumentedLength) {
    for (Cue c : {Cue::fire, Cue::hit, Cue::crash, Cue::level, Cue::over}) {
        const app::CueSound& d = app::cue_sound(c);
        const std::vector<int16_t> v = render_cue(c, d.seconds + 0.5);
        const double end = static_cast<double>(last_nonzero(v) + 1) / kRate;
        EXPECT_NEAR(end, d.seconds, 0.002) << app::cue_name(c);
        // It sounds throughout: no 5 ms stretch of silence before its end.
        for (std::size_t at = 0; at + 220 < static_cast<std::size_t>(d.seconds * kRate); at += 220)
            EXPECT_GT(peak(v, at, at + 220), 0) << app::cue_name(c) << " at " << at;
    }
}

TEST(Sound, EachCuePeaksAtItsDocumentedLevel) {
    for (Cue c : {Cue::fire, Cue::hit, Cue::crash, Cue::level, Cue::over}) {
        const app::CueSound& d = app::cue_sound(c);
        const double want = d.level * 32767;
        const int p = peak(render_cue(c, d.seconds + 0.1));
        EXPECT_LE(p, want + 1) << app::cue_name(c);
        EXPECT_GE(p, want * 0.98) << app::cue_name(c);
    }
}

TEST(Sound, TheFireCueSoundsAtItsDocumentedPitch) {
    const app::CueSound& d = app::cue_sound(Cue::fire);
    ASSERT_EQ(d.start_hz, d.end_hz) << "the fire cue is one pitch";
    ASSERT_EQ(d.start_hz, 880) << "docs/sound.md";
    const std::vector<int16_t> v = render_cue(Cue::fire, d.seconds);
    const std::size_t a = static_cast<std::size_t>(0.005 * kRate), b = static_cast<std::size_t>(0.075 * kRate);
    const double hz = cycles(v, a, b) / (static_cast<double>(b - a) / kRate);
    EXPECT_NEAR(hz, d.start_hz, d.start_hz * 0.02);
    // And a DFT of the same stretch peaks at it (a square's fundamental).
    double best = 0, best_hz = 0;
    for (double f = 200; f <= 2000; f += 5) {
        double re = 0, im = 0;
        for (std::size_t i = a; i < b; ++i) {
            re += v[i] * std::cos(6.283185307179586 * f * static_cast<double>(i) / kRate);
            im += v[i] * std::sin(6.283185307179586 * f * static_cast<double>(i) / kRate);
        }
        if (re * re + im * im > best) best = re * re + im * im, best_hz = f;
    }
    EXPECT_NEAR(best_hz, d.start_hz, d.start_hz * 0.02);
}

// A glide from f0 to f1 over T, exponential: f(t) = f0 (f1/f0)^(t/T), whose cycles from t1 to t2
// are the integral f0 T / ln(f1/f0) ((f1/f0)^(t2/T) - (f1/f0)^(t1/T)).
TEST(Sound, TheLevelAndOverCuesGlideAsDocumented) {
    for (Cue c : {Cue::level, Cue::over}) {
        const app::CueSound& d = app::cue_sound(c);
        const std::vector<int16_t> v = render_cue(c, d.seconds);
        const double r = d.end_hz / d.start_hz, T = d.seconds;
        for (auto [t1, t2] : {std::pair{0.02, 0.12}, {T - 0.15, T - 0.02}}) {
            const double want = d.start_hz * T / std::log(r) * (std::pow(r, t2 / T) - std::pow(r, t1 / T));
            const double got = cycles(v, static_cast<std::size_t>(t1 * kRate), static_cast<std::size_t>(t2 * kRate));
            EXPECT_NEAR(got, want, want * 0.02 + 1) << app::cue_name(c) << " from " << t1 << " s";
        }
    }
}

TEST(Sound, ThrustHumsWhileHeldAndFadesWhenReleased) {
    app::Synth s(kRate);
    std::vector<int16_t> v(static_cast<std::size_t>(kRate / 2));
    s.render(v.data(), static_cast<int>(v.size()));
    EXPECT_EQ(peak(v), 0) << "nothing played: silence";
    s.set_thrust(true);
    s.render(v.data(), static_cast<int>(v.size()));
    const double level = app::cue_sound(Cue::thrust).level * 32767;
    EXPECT_LE(peak(v), level + 1);
    EXPECT_GE(peak(v, v.size() / 2), level * 0.98) << "held: the hum goes on at its level";
    s.set_thrust(false);
    s.render(v.data(), static_cast<int>(v.size()));
    const std::size_t fade = static_cast<std::size_t>(app::cue_sound(Cue::thrust).release_s * kRate) + 1;
    EXPECT_GT(peak(v, 0, fade), 0) << "it fades";
    EXPECT_EQ(peak(v, fade), 0) << "then is silent";
    EXPECT_FALSE(s.active());
}

TEST(Sound, MutedIsSilentAndTheSameCuesMakeTheSameSamples) {
    app::SoundFrame f;
    f.add(Cue::fire), f.add(Cue::crash), f.thrust = true;
    std::vector<int16_t> a(8000), b(8000), m(8000);
    app::Synth s1(kRate), s2(kRate), muted(kRate);
    for (app::Synth* s : {&s1, &s2}) {
        s->apply(f);
        s->render(s == &s1 ? a.data() : b.data(), 8000);
    }
    EXPECT_EQ(a, b);
    EXPECT_GT(peak(a), 0);
    app::SoundFrame fm = f;
    fm.muted = true;
    muted.apply(fm);
    muted.render(m.data(), 8000);
    EXPECT_EQ(peak(m), 0);
    s1.apply(fm);  // muting stops what plays
    s1.render(a.data(), 8000);
    EXPECT_EQ(peak(a), 0);
    // Eight crashes at once stay within int16 (clamped), and a ninth cue takes the oldest voice.
    app::Synth loud(kRate);
    for (int i = 0; i < 9; ++i) loud.play(Cue::crash);
    loud.render(a.data(), 8000);
    EXPECT_LE(peak(a), 32767);
}

// ---- the session's cues ------------------------------------------------------------------

long last_bullet(const std::string& line) {
    long best = 0;
    for (std::size_t at = line.find("\"bullet "); at != std::string::npos; at = line.find("\"bullet ", at + 1))
        best = std::max(best, std::atol(line.c_str() + at + 8));
    return best;
}

TEST(Sound, TheSessionCuesFireAndHitInTheStepsTheGameDoesThem) {
    app::Options o = app::defaults(app::Command::run);
    o.scene = std::string(NONEUCLID_SOURCE_DIR) + "/tests/files/data/game.toml";
    o.engine = world::engine_named("double");
    const world::Scene scene = app::load_scene(o);
    const auto s = app::make_session(app::world_kind(o, scene), scene, app::session_options(o, scene, "keys", app::world_kind(o, scene)), render::builtin_font(), nullptr);
    int fires = 0, hits = 0, thrusts = 0;
    long bullet = 0;
    std::string line;
    for (long f = 0; f < 900; ++f) {
        if (f == 10) s->queue({world::Action::fire, true});   // a new game
        if (f == 12) s->queue({world::Action::fire, false});
        if (f == 30) s->queue({world::Action::fire, true});   // held: a shot every cooldown
        if (f == 100) s->queue({world::Action::thrust, true});
        if (f == 130) s->queue({world::Action::thrust, false});
        if (f == 5) s->queue({world::Action::thrust, true});  // no ship yet: no hum
        if (f == 8) s->queue({world::Action::thrust, false});
        s->step();
        line.clear();
        s->dump(320, 200, line);
        const long now = last_bullet(line);
        const app::SoundFrame c = s->sound();
        EXPECT_EQ(c.has(Cue::fire), now > bullet) << "frame " << f << ": " << line;
        EXPECT_EQ(c.has(Cue::hit), line.find("{\"hit\":") != std::string::npos) << "frame " << f;
        EXPECT_EQ(c.has(Cue::crash), line.find("{\"crash\":") != std::string::npos) << "frame " << f;
        const bool ship = line.find("\"kind\":\"ship\"") != std::string::npos;  // (dump leaves an inactive body out)
        EXPECT_EQ(c.thrust, f >= 100 && f < 130 && ship) << "frame " << f;
        EXPECT_FALSE(c.muted);
        bullet = std::max(bullet, now);
        fires += c.has(Cue::fire), hits += c.has(Cue::hit), thrusts += c.thrust;
    }
    EXPECT_GT(fires, 5);
    EXPECT_GT(hits, 0);
    EXPECT_GT(thrusts, 0);
    // The mute key turns the sound off and on.
    s->queue({world::Action::mute, true});
    s->step();
    EXPECT_TRUE(s->sound().muted);
    s->queue({world::Action::mute, false});
    s->queue({world::Action::mute, true});
    s->step();
    EXPECT_FALSE(s->sound().muted);
}

}  // namespace
