// ALSA's sound (platform/linux/alsa_sound.cpp) through a real libasound: its `file` PCM plugin
// (alsa.conf's pcm.file, a null device behind it that takes every sample at once) writes what
// the program plays into a raw file, which must hold exactly the synthesiser's samples (after
// the half buffer of silence ahead of them), frame by frame. Then `noneuclid run --sound` with a
// scripted game: its first shot sounds in the frame `noneuclid dump` shows the first bullet.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "app/platform.hpp"
#include "app/sound.hpp"

namespace {

using namespace noneuclid;
using app::Cue;

std::string temp(const std::string& name) {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir && *dir ? dir : "/tmp") + "/noneuclid-alsa-" + std::to_string(::getpid()) + "-" + name;
}
std::vector<int16_t> read_raw(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<int16_t> out(bytes.size() / 2);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<int16_t>(static_cast<uint8_t>(bytes[2 * i]) | (static_cast<uint8_t>(bytes[2 * i + 1]) << 8));
    return out;
}
// The samples due by the end of frame k (1/60 s a frame), as the ALSA sink counts them.
long due(long k, int rate) { return static_cast<long>(std::llround(static_cast<double>(k) / 60 * rate)); }

TEST(AlsaSound, TheFilePluginGetsTheSynthesisersSamplesFrameByFrame) {
    for (int rate : {44100, 22050}) {
        const std::string path = temp("direct.raw");
        std::remove(path.c_str());
        std::vector<app::SoundFrame> frames(90);
        frames[0].add(Cue::fire);
        frames[20].add(Cue::hit);
        for (int f = 30; f < 50; ++f) frames[static_cast<std::size_t>(f)].thrust = true;
        frames[40].add(Cue::level);
        {
            platform::SoundSpec spec;
            spec.device = "file:'" + path + "',raw", spec.rate = rate;
            std::string error;
            const std::unique_ptr<app::SoundOut> out = platform::open_sound(spec, error);
            ASSERT_NE(out, nullptr) << error;
            for (const app::SoundFrame& f : frames) out->frame(f, 1.0 / 60);
        }
        const std::vector<int16_t> got = read_raw(path);
        std::remove(path.c_str());
        const long total = due(static_cast<long>(frames.size()), rate);
        ASSERT_GE(static_cast<long>(got.size()), total);
        const long headroom = static_cast<long>(got.size()) - total;
        EXPECT_LE(headroom, rate / 10) << "half a buffer of silence, the buffer ~80 ms";
        for (long i = 0; i < headroom; ++i) ASSERT_EQ(got[static_cast<std::size_t>(i)], 0) << i;
        // The reference: the synthesiser fed the same frames.
        app::Synth synth(rate);
        std::vector<int16_t> want;
        for (std::size_t k = 0; k < frames.size(); ++k) {
            synth.apply(frames[k]);
            const long n = due(static_cast<long>(k) + 1, rate) - due(static_cast<long>(k), rate);
            std::vector<int16_t> chunk(static_cast<std::size_t>(n));
            synth.render(chunk.data(), static_cast<int>(n));
            want.insert(want.end(), chunk.begin(), chunk.end());
        }
        const std::vector<int16_t> sound(got.begin() + headroom, got.end());
        EXPECT_TRUE(sound == want) << rate << " Hz: the file is not the synthesiser's rendering";
        // And it is sound: the fire cue's blip at the start, the hit's at frame 20.
        int early = 0, hit = 0;
        for (long i = 0; i < due(1, rate); ++i) early = std::max(early, std::abs(static_cast<int>(sound[static_cast<std::size_t>(i)])));
        for (long i = due(20, rate); i < due(21, rate); ++i) hit = std::max(hit, std::abs(static_cast<int>(sound[static_cast<std::size_t>(i)])));
        EXPECT_GT(early, 0.9 * app::cue_sound(Cue::fire).level * 32767) << rate;
        EXPECT_GT(hit, 0.5 * app::cue_sound(Cue::hit).level * 32767) << rate;
    }
}

TEST(AlsaSound, ADeviceThatCannotBeOpenedIsOneSentence) {
    platform::SoundSpec spec;
    spec.device = "no_such_pcm_device";
    std::string error;
    EXPECT_EQ(platform::open_sound(spec, error), nullptr);
    EXPECT_NE(error.find("cannot open the sound device 'no_such_pcm_device'"), std::string::npos) << error;
    EXPECT_NE(error.find("--sound-device"), std::string::npos) << error;
}

#ifdef NONEUCLID_BINARY
std::string run(const std::string& command) {
    std::string out;
    if (std::FILE* p = popen(command.c_str(), "r")) {
        char buf[4096];
        for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
        EXPECT_EQ(pclose(p), 0) << command;
    }
    return out;
}

// The program's own path: `run --sound` on the headless display, a scripted game (a tap of fire
// starts it, fire held fires), its sound into the file plugin.
TEST(AlsaSound, RunPlaysTheFirstShotInTheFrameItIsFired) {
    const std::string raw = temp("run.raw"), actions = temp("actions.txt");
    {
        std::ofstream a(actions);
        a << "0.1 tap fire\n0.5 press fire\n";
    }
    const std::string scene = std::string(NONEUCLID_SOURCE_DIR) + "/tests/files/data/game.toml";
    const long frames = 120;
    const std::string common = " --scene " + scene + " --actions " + actions + " --frames " + std::to_string(frames);
    const std::string said = run(std::string(NONEUCLID_BINARY) + " run --display png --attract 0 --screenshot " +
                                 temp("run.png") + " --scores none --sound --sound-device \"file:'" + raw + "',raw\"" +
                                 common + " 2>&1");
    EXPECT_NE(said.find("sound on 'file:"), std::string::npos) << said;
    // The first frame `dump` shows a bullet in (the same actions, the same steps).
    const std::string dump = run(std::string(NONEUCLID_BINARY) + " dump" + common + " 2>/dev/null");
    long shot = -1, k = 0;
    for (std::size_t at = 0, end; (end = dump.find('\n', at)) != std::string::npos; at = end + 1, ++k)
        if (dump.substr(at, end - at).find("\"bullet ") != std::string::npos) {
            shot = k;
            break;
        }
    ASSERT_GT(shot, 0) << "dump shows no shot";
    const std::vector<int16_t> got = read_raw(raw);
    std::remove(raw.c_str()), std::remove(actions.c_str()), std::remove(temp("run.png").c_str());
    const long total = due(frames, 44100);
    ASSERT_GE(static_cast<long>(got.size()), total);
    const long headroom = static_cast<long>(got.size()) - total;
    // dump's line 0 is the world before the first step; line k after step k, which run's frame
    // k renders as the samples from due(k - 1) to due(k).
    long first = -1;
    for (std::size_t i = static_cast<std::size_t>(headroom); i < got.size() && first < 0; ++i)
        if (got[i] != 0) first = static_cast<long>(i) - headroom;
    ASSERT_GE(first, 0) << "silence";
    EXPECT_GE(first, due(shot - 1, 44100));
    EXPECT_LT(first, due(shot, 44100));
    // What sounds from there is the fire cue (a square's blip), alone.
    app::Synth synth(44100);
    synth.play(Cue::fire);
    std::vector<int16_t> want(static_cast<std::size_t>(app::cue_sound(Cue::fire).seconds * 44100));
    synth.render(want.data(), static_cast<int>(want.size()));
    const long start = headroom + due(shot - 1, 44100);
    ASSERT_GE(static_cast<long>(got.size()), start + static_cast<long>(want.size()));
    EXPECT_TRUE(std::equal(want.begin(), want.end(), got.begin() + start)) << "not the fire cue";
}
#endif

}  // namespace
