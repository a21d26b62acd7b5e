#include "app/sound.hpp"

#include <cmath>

namespace noneuclid::app {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// The cues, in Cue's order (docs/sound.md has this table in words).
constexpr CueSound kCues[kCueCount] = {
    {CueSound::square, 880, 880, 0.08, 0.25, 0.002, 0.02},  // fire: a short bright blip
    {CueSound::noise, 3000, 3000, 0.15, 0.40, 0.002, 0.10},  // hit: a crack
    {CueSound::noise, 800, 800, 0.60, 0.60, 0.005, 0.50},    // crash: a long dull rumble
    {CueSound::sine, 440, 880, 0.40, 0.35, 0.010, 0.10},     // level: a rising whoop, an octave
    {CueSound::sine, 440, 110, 1.00, 0.40, 0.010, 0.30},     // over: a falling tone, two octaves
    {CueSound::noise, 150, 150, 0, 0.20, 0.020, 0.020},      // thrust: a low hum while held
};

const char* const kNames[kCueCount] = {"fire", "hit", "crash", "level", "over", "thrust"};

// The one-pole low-pass's coefficient at fc, and the gain that brings filtered white noise
// (uniform in [-1, 1], standard deviation 1/sqrt(3)) back to a standard deviation of 1/2, so
// that a noise cue reaches its level (clipped there) whatever its cutoff.
double low_pass(double fc, int rate) { return 1 - std::exp(-kTwoPi * fc / rate); }
double noise_gain(double a) { return 0.5 / (std::sqrt(a / (2 - a)) / std::sqrt(3.0)); }
double clamp1(double x) { return x < -1 ? -1 : (x > 1 ? 1 : x); }

}  // namespace

const char* cue_name(Cue c) { return kNames[static_cast<int>(c)]; }
const CueSound& cue_sound(Cue c) { return kCues[static_cast<int>(c)]; }

Synth::Synth(int rate) : rate_(rate > 0 ? rate : 44100) {
    for (int i = 0; i < kCueCount; ++i) {
        low_pass_[i] = low_pass(kCues[i].start_hz, rate_);
        noise_gain_[i] = noise_gain(low_pass_[i]);
    }
}

void Synth::play(Cue c) {
    if (muted_) return;
    if (c == Cue::thrust) {
        thrust_ = true;
        return;
    }
    Voice* v = &voices_[0];
    for (Voice& w : voices_) {
        if (!w.on) {
            v = &w;
            break;
        }
        if (w.age < v->age) v = &w;
    }
    *v = Voice{};
    v->on = true, v->cue = c, v->age = ++started_;
    const CueSound& s = cue_sound(c);
    v->length = static_cast<long>(std::lround(s.seconds * rate_));
    v->hz = s.start_hz;  // f(t) = start (end / start)^(t / length): a constant factor a sample
    v->glide = std::pow(s.end_hz / s.start_hz, 1.0 / static_cast<double>(v->length));
}

void Synth::set_muted(bool m) {
    muted_ = m;
    if (!m) return;
    for (Voice& v : voices_) v.on = false;
    thrust_gain_ = 0, thrust_low_ = 0;
}

void Synth::apply(const SoundFrame& f) {
    if (f.muted != muted_) set_muted(f.muted);
    for (int i = 0; i < kCueCount; ++i)
        if (f.has(static_cast<Cue>(i))) play(static_cast<Cue>(i));
    thrust_ = f.thrust && !muted_;
}

bool Synth::active() const {
    for (const Voice& v : voices_)
        if (v.on) return true;
    return thrust_ || thrust_gain_ > 0;
}

double Synth::noise() {  // xorshift32, uniform in [-1, 1)
    noise_ ^= noise_ << 13, noise_ ^= noise_ >> 17, noise_ ^= noise_ << 5;
    return static_cast<double>(noise_) / 2147483648.0 - 1;
}

double Synth::envelope(const Voice& v) const {
    const CueSound& s = cue_sound(v.cue);
    const double t = static_cast<double>(v.t) / rate_, left = static_cast<double>(v.length - v.t) / rate_;
    double e = 1;
    if (t < s.attack_s) e = t / s.attack_s;
    if (left < s.release_s) e = std::fmin(e, left / s.release_s);
    return e < 0 ? 0 : e;
}

double Synth::sample(Voice& v) {
    const CueSound& s = cue_sound(v.cue);
    double x = 0;
    if (s.wave == CueSound::noise) {
        const int i = static_cast<int>(v.cue);
        v.low += low_pass_[i] * (noise() - v.low);
        x = clamp1(v.low * noise_gain_[i]);
    } else {
        x = s.wave == CueSound::square ? (v.phase < 0.5 ? 1 : -1) : std::sin(kTwoPi * v.phase);
        v.phase += v.hz / rate_;
        v.phase -= std::floor(v.phase);
        v.hz *= v.glide;
    }
    x *= s.level * envelope(v);
    if (++v.t >= v.length) v.on = false;
    return x;
}

void Synth::render(int16_t* out, int frames) {
    const CueSound& th = cue_sound(Cue::thrust);
    const int t = static_cast<int>(Cue::thrust);
    const double a = low_pass_[t], g = noise_gain_[t];
    const double fade = 1.0 / (th.attack_s * rate_);
    for (int i = 0; i < frames; ++i) {
        double mix = 0;
        for (Voice& v : voices_)
            if (v.on) mix += sample(v);
        if (thrust_ || thrust_gain_ > 0) {
            thrust_gain_ = thrust_ ? std::fmin(1, thrust_gain_ + fade) : std::fmax(0, thrust_gain_ - fade);
            thrust_low_ += a * (noise() - thrust_low_);
            mix += clamp1(thrust_low_ * g) * th.level * thrust_gain_;
        }
        out[i] = static_cast<int16_t>(std::lround(clamp1(mix) * 32767));
    }
}

}  // namespace noneuclid::app
