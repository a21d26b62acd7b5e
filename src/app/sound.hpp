// Sound (docs/sound.md): a few cues the game plays (fire, hit, crash, level, over, and a hum
// while thrust is held), each synthesised here, no sample files: a square or sine tone with a
// pitch glide, or a noise burst, shaped by an envelope. The synthesiser renders 16-bit mono PCM
// into the caller's buffer from a fixed array of voices, deterministically (the noise is an
// xorshift), and allocates nothing. The session says once a step which cues began
// (SoundFrame); the frame loop hands that to a SoundOut, which a platform implements (ALSA on
// Linux, Web Audio in the page) and which renders the samples itself.
#pragma once

#include <cstdint>

namespace noneuclid::app {

enum class Cue : uint8_t { fire, hit, crash, level, over, thrust };
inline constexpr int kCueCount = 6;
const char* cue_name(Cue c);

// How a cue sounds. A tone glides from start_hz to end_hz (exponentially, so a glide is even in
// pitch); noise is white noise through a one-pole low-pass at start_hz. `level` is the peak as a
// fraction of int16's full scale; the envelope rises linearly over attack_s to it, holds, then
// falls linearly to 0 over the last release_s. thrust has no length: it sounds while held.
struct CueSound {
    enum Wave : uint8_t { square, sine, noise };
    Wave wave;
    double start_hz, end_hz;
    double seconds;  // the whole cue, attack and release included
    double level;
    double attack_s, release_s;
};
const CueSound& cue_sound(Cue c);

// What one step asks of the sound: the cues that began in it, whether thrust is held, whether
// the sound is muted (the mute key).
struct SoundFrame {
    uint8_t cues = 0;  // a bit for each Cue that began
    bool thrust = false;
    bool muted = false;
    bool has(Cue c) const { return cues & (1u << static_cast<unsigned>(c)); }
    void add(Cue c) { cues = static_cast<uint8_t>(cues | (1u << static_cast<unsigned>(c))); }
};

class Synth {
public:
    static constexpr int kVoices = 8;  // a ninth cue replaces the oldest voice
    explicit Synth(int rate = 44100);
    int rate() const { return rate_; }

    void play(Cue c);
    void set_thrust(bool on) { thrust_ = on; }
    // Muted: nothing sounds, the voices playing stop, and cues are ignored until unmuted.
    void set_muted(bool m);
    bool muted() const { return muted_; }
    // A step's cues and thrust, and its mute.
    void apply(const SoundFrame& f);
    // Mixes `frames` samples into out (replacing what it held); silence when nothing plays.
    void render(int16_t* out, int frames);
    // Whether any voice (or the thrust hum) sounds.
    bool active() const;

private:
    struct Voice {
        bool on = false;
        Cue cue = Cue::fire;
        long t = 0, length = 0;  // samples played, of the cue's length (thrust: -1, held)
        double phase = 0;         // cycles, in [0, 1)
        double hz = 0, glide = 1; // a tone's frequency now, and its factor a sample
        double low = 0;           // the noise's low-pass state
        long age = 0;             // when it started, to replace the oldest
    };
    double sample(Voice& v);
    double envelope(const Voice& v) const;
    double noise();

    int rate_;
    double low_pass_[kCueCount], noise_gain_[kCueCount];  // each noise cue's filter, made once
    Voice voices_[kVoices];
    bool thrust_ = false, muted_ = false;
    double thrust_gain_ = 0;  // the hum fades in and out (20 ms) instead of clicking
    double thrust_low_ = 0;
    uint32_t noise_ = 0x9E3779B9u;
    long started_ = 0;
};

// Where a run's sound goes (a platform's: platform::open_sound). Told once a frame, after the
// step, what that step asked for and how much world time it was: it renders that much sound.
class SoundOut {
public:
    virtual ~SoundOut() = default;
    virtual void frame(const SoundFrame& f, double seconds) = 0;
};

}  // namespace noneuclid::app
