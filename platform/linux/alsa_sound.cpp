// open_sound (app/platform.hpp) through ALSA: 16-bit mono PCM, opened non-blocking. Each frame
// renders the frame's world time of sound (app/sound.hpp) and writes what the device's buffer
// takes, so that sound keeps to the world's time and the frame loop never waits on the device.
// The buffer holds about kLatencyUs, and the first write puts half of it in silence ahead of the
// sound: room for frames that come late. Frames slower than the device plays (a run below its
// frame rate) use that room up; the underrun (xrun) that follows is recovered with
// snd_pcm_recover and the room made again.
#include <alsa/asoundlib.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <vector>

#include "app/platform.hpp"

namespace noneuclid::platform {
namespace {

constexpr unsigned kLatencyUs = 80000;

// libasound's own messages on stderr (its file and line) are left out: open_sound's sentence
// says what went wrong, once.
void quiet(const char*, int, const char*, int, const char*, ...) {}

class AlsaSound final : public app::SoundOut {
public:
    AlsaSound(snd_pcm_t* pcm, int rate, snd_pcm_uframes_t buffer)
        : pcm_(pcm), synth_(rate), buffer_size_(static_cast<long>(buffer)), samples_(buffer) {}
    ~AlsaSound() override {
        snd_pcm_drop(pcm_);
        snd_pcm_close(pcm_);
    }

    void frame(const app::SoundFrame& f, double seconds) override {
        synth_.apply(f);
        world_ += seconds;
        const long long due = std::llround(world_ * synth_.rate());
        long n = static_cast<long>(due - due_);
        due_ = due;
        snd_pcm_sframes_t avail = snd_pcm_avail_update(pcm_);
        if (avail < 0) {  // an underrun: start again, with the headroom of a first frame
            if (snd_pcm_recover(pcm_, static_cast<int>(avail), 1) < 0) return;
            headroom_ = true;
            avail = snd_pcm_avail_update(pcm_);
            if (avail < 0) return;
        }
        if (headroom_) {  // half a buffer of silence ahead of the first sound: room for late frames
            headroom_ = false;
            const long h = std::min(buffer_size_ / 2, static_cast<long>(avail));
            std::fill(samples_.begin(), samples_.begin() + h, int16_t{0});
            if (write(h) < 0) return;
            avail -= h;
        }
        if (n > static_cast<long>(avail)) n = static_cast<long>(avail);  // the rest is dropped
        if (n <= 0) return;
        synth_.render(samples_.data(), static_cast<int>(n));
        write(n);
    }

private:
    long write(long n) {
        const snd_pcm_sframes_t w = snd_pcm_writei(pcm_, samples_.data(), static_cast<snd_pcm_uframes_t>(n));
        if (w < 0 && w != -EAGAIN) snd_pcm_recover(pcm_, static_cast<int>(w), 1), headroom_ = true;
        return w;
    }

    snd_pcm_t* pcm_;
    app::Synth synth_;
    long buffer_size_;
    std::vector<int16_t> samples_;  // one buffer's worth, made once
    double world_ = 0;              // world seconds so far
    long long due_ = 0;             // samples of world time so far (written or dropped)
    bool headroom_ = true;          // the next write starts with half a buffer of silence
};

}  // namespace

std::unique_ptr<app::SoundOut> open_sound(const SoundSpec& spec, std::string& error) {
    snd_lib_error_set_handler(quiet);
    snd_pcm_t* pcm = nullptr;
    const char* fix = "; check --sound-device (aplay -L lists the devices), or run without --sound";
    int e = snd_pcm_open(&pcm, spec.device.c_str(), SND_PCM_STREAM_PLAYBACK, SND_PCM_NONBLOCK);
    if (e < 0) {
        error = "cannot open the sound device '" + spec.device + "': " + snd_strerror(e) + fix + ".";
        return nullptr;
    }
    e = snd_pcm_set_params(pcm, SND_PCM_FORMAT_S16, SND_PCM_ACCESS_RW_INTERLEAVED, 1,
                           static_cast<unsigned>(spec.rate), 1, kLatencyUs);
    snd_pcm_uframes_t buffer = 0, period = 0;
    if (e >= 0) e = snd_pcm_get_params(pcm, &buffer, &period);
    // The device starts playing once the headroom and a frame are in (snd_pcm_set_params waits
    // for a full buffer): the sound is then about half a buffer behind the picture, not a whole.
    snd_pcm_sw_params_t* sw = nullptr;
    if (e >= 0 && snd_pcm_sw_params_malloc(&sw) >= 0) {
        if (snd_pcm_sw_params_current(pcm, sw) >= 0 && snd_pcm_sw_params_set_start_threshold(pcm, sw, buffer / 2) >= 0)
            snd_pcm_sw_params(pcm, sw);
        snd_pcm_sw_params_free(sw);
    }
    if (e < 0 || buffer == 0) {
        error = "cannot play 16-bit mono sound at " + std::to_string(spec.rate) + " Hz on '" + spec.device +
                "': " + (e < 0 ? snd_strerror(e) : "no buffer") + fix + ".";
        snd_pcm_close(pcm);
        return nullptr;
    }
    return std::make_unique<AlsaSound>(pcm, spec.rate, buffer);
}

}  // namespace noneuclid::platform
