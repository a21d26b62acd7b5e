// Kiosk input (platform/linux): what runs without GPIO or input devices. The configuration
// checks, the chip search against a fake /dev and fake labels, the sentences for missing chips
// and devices (checked against what this machine really has), the debounce state machine on a
// synthetic clock and print_input_events over a pipe: test_debounce.cpp. The backends against a real kernel:
// tests/system/input.sh (gpio-sim and uinput under qemu).
#include <dirent.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "buttons.hpp"
#include "linux/gpio_common.hpp"
#include "linux/input.hpp"

namespace p = noneuclid::platform;
namespace gd = noneuclid::platform::gpio_detail;
using noneuclid::test::two_buttons;
using noneuclid::world::Action;
using noneuclid::world::InputEvent;

namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

bool dir_has_entry_starting(const char* dir, const char* prefix) {
    DIR* d = opendir(dir);
    if (!d) return false;
    bool found = false;
    while (const dirent* e = readdir(d))
        if (std::strncmp(e->d_name, prefix, std::strlen(prefix)) == 0) found = true;
    closedir(d);
    return found;
}


// ---------------------------------------------------------------------------------------------
// Configuration sentences
// ---------------------------------------------------------------------------------------------

TEST(GpioConfig, GoodConfigHasNoError) { EXPECT_EQ(gd::check_config(two_buttons()), ""); }

TEST(GpioConfig, NoButtons) {
    auto c = two_buttons();
    c.buttons.clear();
    EXPECT_TRUE(contains(gd::check_config(c), "no GPIO buttons are configured"));
}

TEST(GpioConfig, NoChip) {
    auto c = two_buttons();
    c.chips.clear();
    const auto e = gd::check_config(c);
    EXPECT_TRUE(contains(e, "no GPIO chip is configured")) << e;
    EXPECT_TRUE(contains(e, "gpiodetect")) << e;
}

TEST(GpioConfig, LineGivenTwiceNamesBothControls) {
    auto c = two_buttons();
    c.buttons[1].line = 17;
    const auto e = gd::check_config(c);
    EXPECT_TRUE(contains(e, "GPIO line 17 is given to both thrust and left")) << e;
}

TEST(GpioConfig, DebounceTooLong) {
    auto c = two_buttons();
    c.debounce_ms = 5000;
    EXPECT_TRUE(contains(gd::check_config(c), "debounce of 5000 ms is too long"));
}

TEST(GpioConfig, LineDescriptionNamesPinAndControl) {
    EXPECT_EQ(gd::describe_line({Action::thrust, 17, 11}), "GPIO line 17 (thrust, header pin 11)");
    EXPECT_EQ(gd::describe_line({Action::reset, 5, 0}), "GPIO line 5 (reset)");
}

TEST(GpioConfig, RequestErrors) {
    const p::GpioButton b{Action::thrust, 17, 11};
    auto busy = gd::request_error(b, "pinctrl-bcm2711 (/dev/gpiochip0)", EBUSY, "gpio_keys");
    EXPECT_TRUE(contains(busy, "GPIO line 17 (thrust, header pin 11) on pinctrl-bcm2711 (/dev/gpiochip0) is in use by "
                               "\"gpio_keys\"")) << busy;
    EXPECT_TRUE(contains(busy, "dtoverlay=gpio-key")) << busy;
    auto busy_unknown = gd::request_error(b, "chip", EBUSY, "");
    EXPECT_TRUE(contains(busy_unknown, "another process or a gpio-key overlay")) << busy_unknown;
    for (int err : {EACCES, EPERM}) {
        auto perm = gd::request_error(b, "chip", err, "");
        EXPECT_TRUE(contains(perm, "sudo usermod -aG gpio $USER")) << perm;
        EXPECT_TRUE(contains(perm, "log in again")) << perm;
    }
    auto range = gd::line_range_error({Action::left, 60, 0}, "pinctrl-bcm2711 (/dev/gpiochip0)", 58);
    EXPECT_TRUE(contains(range, "GPIO line 60 (left) does not exist on pinctrl-bcm2711 (/dev/gpiochip0), which has 58 "
                                "lines (0 to 57)")) << range;
}

// ---------------------------------------------------------------------------------------------
// The chip search, against a fake /dev (files named gpiochipN) and a fake probe
// ---------------------------------------------------------------------------------------------

class FakeDev : public ::testing::Test {
protected:
    void SetUp() override {
        char tmpl[] = "/tmp/noneuclid-gpio-XXXXXX";
        ASSERT_NE(mkdtemp(tmpl), nullptr);
        dir_ = tmpl;
        // Out of order and with a non-chip entry, to check the numeric sort and the filter.
        for (const char* n : {"gpiochip10", "gpiochip2", "gpiochip0", "gpiochipX", "null"}) {
            int fd = ::open((dir_ + "/" + n).c_str(), O_CREAT | O_WRONLY, 0600);
            ASSERT_GE(fd, 0);
            close(fd);
        }
    }
    void TearDown() override {
        for (const char* n : {"gpiochip10", "gpiochip2", "gpiochip0", "gpiochipX", "null"})
            unlink((dir_ + "/" + n).c_str());
        rmdir(dir_.c_str());
    }
    std::string dir_;
};

// gpiochip0 "pinctrl-bcm2711" (58 lines), gpiochip2 "raspberrypi-exp-gpio" (8), gpiochip10: EACCES.
int fake_probe(const std::string& path, gd::ChipInfo& info) {
    if (path.size() >= 10 && path.compare(path.size() - 10, 10, "gpiochip10") == 0) return EACCES;
    if (path.size() >= 9 && path.compare(path.size() - 9, 9, "gpiochip0") == 0) {
        info = {"pinctrl-bcm2711", 58};
        return 0;
    }
    if (path.size() >= 9 && path.compare(path.size() - 9, 9, "gpiochip2") == 0) {
        info = {"raspberrypi-exp-gpio", 8};
        return 0;
    }
    return ENOTTY;
}
int fake_probe_all_open(const std::string& path, gd::ChipInfo& info) {
    int e = fake_probe(path, info);
    if (e == EACCES) info = {"gpio-sim.0-node0", 8};
    return e == EACCES ? 0 : e;
}

TEST_F(FakeDev, ListsChipsInNumericOrder) {
    const auto chips = gd::list_chips(dir_);
    ASSERT_EQ(chips.size(), 3u);
    EXPECT_EQ(chips[0], dir_ + "/gpiochip0");
    EXPECT_EQ(chips[1], dir_ + "/gpiochip2");
    EXPECT_EQ(chips[2], dir_ + "/gpiochip10");
}

TEST_F(FakeDev, FirstMatchingLabelWins) {
    p::GpioConfig c = two_buttons();
    c.chips = {"pinctrl-rp1", "raspberrypi-exp-gpio", "pinctrl-bcm2711"};
    std::string path, error;
    gd::ChipInfo info;
    ASSERT_TRUE(gd::find_chip(c, fake_probe, path, info, error, dir_)) << error;
    EXPECT_EQ(path, dir_ + "/gpiochip2");
    EXPECT_EQ(info.label, "raspberrypi-exp-gpio");
    EXPECT_EQ(info.num_lines, 8u);
}

TEST_F(FakeDev, PathEntry) {
    p::GpioConfig c = two_buttons();
    c.chips = {dir_ + "/gpiochip0"};
    std::string path, error;
    gd::ChipInfo info;
    ASSERT_TRUE(gd::find_chip(c, fake_probe, path, info, error, dir_)) << error;
    EXPECT_EQ(path, dir_ + "/gpiochip0");
    EXPECT_EQ(info.label, "pinctrl-bcm2711");
}

TEST_F(FakeDev, NoMatchListsWhatWasTriedAndWhatExists) {
    p::GpioConfig c = two_buttons();
    c.chips = {"pinctrl-rp1", "pinctrl-bcm2835"};
    std::string path, error;
    gd::ChipInfo info;
    ASSERT_FALSE(gd::find_chip(c, fake_probe_all_open, path, info, error, dir_));
    EXPECT_TRUE(contains(error, "no GPIO chip matches pinctrl-rp1, pinctrl-bcm2835")) << error;
    EXPECT_TRUE(contains(error, dir_ + "/gpiochip0 \"pinctrl-bcm2711\"")) << error;
    EXPECT_TRUE(contains(error, dir_ + "/gpiochip10 \"gpio-sim.0-node0\"")) << error;
    EXPECT_TRUE(contains(error, "gpiodetect")) << error;
}

TEST_F(FakeDev, UnreadableChipGivesTheGroupSentence) {
    p::GpioConfig c = two_buttons();
    c.chips = {"pinctrl-rp1"};
    std::string path, error;
    gd::ChipInfo info;
    ASSERT_FALSE(gd::find_chip(c, fake_probe, path, info, error, dir_));
    EXPECT_TRUE(contains(error, "no permission to open " + dir_ + "/gpiochip10")) << error;
    EXPECT_TRUE(contains(error, "sudo usermod -aG gpio $USER")) << error;
}

TEST_F(FakeDev, MissingPathSaysItDoesNotExist) {
    p::GpioConfig c = two_buttons();
    c.chips = {dir_ + "/gpiochip7"};
    std::string path, error;
    gd::ChipInfo info;
    ASSERT_FALSE(gd::find_chip(c, fake_probe, path, info, error, dir_));
    EXPECT_TRUE(contains(error, dir_ + "/gpiochip7 does not exist")) << error;
}

// ---------------------------------------------------------------------------------------------
// open_gpio / open_evdev on this machine: the sentences, checked against what /dev really has
// ---------------------------------------------------------------------------------------------

#if NONEUCLID_HAVE_GPIOD
TEST(OpenGpio, VersionNamesTheApi) {
    const std::string v = p::gpiod_version();
    EXPECT_TRUE(contains(v, "(v" + std::to_string(NONEUCLID_GPIOD_MAJOR) + " API)")) << v;
    EXPECT_EQ(v.substr(0, 1), std::to_string(NONEUCLID_GPIOD_MAJOR)) << v;
}

TEST(OpenGpio, ConfigErrorComesFirst) {
    auto c = two_buttons();
    c.buttons.clear();
    std::string error;
    EXPECT_EQ(p::open_gpio(c, error), nullptr);
    EXPECT_TRUE(contains(error, "no GPIO buttons are configured")) << error;
}

TEST(OpenGpio, MissingChipPath) {
    const std::string missing = "/dev/gpiochip97";
    struct stat st {};
    ASSERT_NE(stat(missing.c_str(), &st), 0) << missing << " exists here";
    auto c = two_buttons();
    c.chips = {missing};
    std::string error;
    EXPECT_EQ(p::open_gpio(c, error), nullptr);
    EXPECT_TRUE(contains(error, "/dev/gpiochip97 does not exist")) << error;
}

TEST(OpenGpio, NotAChip) {
    auto c = two_buttons();
    c.chips = {"/dev/null"};
    std::string error;
    EXPECT_EQ(p::open_gpio(c, error), nullptr);
    EXPECT_TRUE(contains(error, "/dev/null is not a GPIO chip")) << error;
}

TEST(OpenGpio, NoChipWithTheLabel) {
    auto c = two_buttons();
    c.chips = {"noneuclid-no-such-label", "another-label"};
    std::string error;
    EXPECT_EQ(p::open_gpio(c, error), nullptr);
    EXPECT_TRUE(contains(error, "no GPIO chip matches noneuclid-no-such-label, another-label")) << error;
    if (!dir_has_entry_starting("/dev", "gpiochip")) {
        EXPECT_TRUE(contains(error, "this system has no /dev/gpiochip* devices")) << error;
    } else {
        EXPECT_TRUE(contains(error, "the chips here are /dev/gpiochip")) << error;
    }
}
#endif

p::EvdevConfig two_keys() {
    p::EvdevConfig c;
    c.keys = {{Action::thrust, 103}, {Action::left, 105}};
    return c;
}

TEST(OpenEvdev, NoKeys) {
    p::EvdevConfig c;
    std::string error;
    EXPECT_EQ(p::open_evdev(c, error), nullptr);
    EXPECT_TRUE(contains(error, "no evdev keys are configured")) << error;
}

TEST(OpenEvdev, CodeOutOfRange) {
    for (unsigned code : {0u, 768u, 100000u}) {
        auto c = two_keys();
        c.keys[1].code = code;
        std::string error;
        EXPECT_EQ(p::open_evdev(c, error), nullptr);
        EXPECT_TRUE(contains(error, "key code " + std::to_string(code) + " (left) is not an evdev key")) << error;
    }
}

TEST(OpenEvdev, CodeGivenTwice) {
    auto c = two_keys();
    c.keys[1].code = 103;
    std::string error;
    EXPECT_EQ(p::open_evdev(c, error), nullptr);
    EXPECT_TRUE(contains(error, "key code 103 is given to both thrust and left")) << error;
}

TEST(OpenEvdev, MissingDevice) {
    auto c = two_keys();
    c.device = "/dev/input/by-id/noneuclid-no-such-keyboard";
    std::string error;
    EXPECT_EQ(p::open_evdev(c, error), nullptr);
    EXPECT_TRUE(contains(error, c.device + " does not exist")) << error;
}

TEST(OpenEvdev, NotAKeyDevice) {
    auto c = two_keys();
    c.device = "/dev/null";
    std::string error;
    EXPECT_EQ(p::open_evdev(c, error), nullptr);
    EXPECT_TRUE(contains(error, "/dev/null has none of the key codes 103, 105")) << error;
}

TEST(OpenEvdev, ScanNamesTheCodesLookedFor) {
    auto c = two_keys();
    std::string error;
    auto src = p::open_evdev(c, error);
    if (src) GTEST_SKIP() << "this machine has a key device: " << src->describe();
    EXPECT_TRUE(contains(error, "key codes 103, 105")) << error;
    if (!dir_has_entry_starting("/dev/input", "event")) {
        EXPECT_TRUE(contains(error, "this system has no /dev/input/event* devices")) << error;
    }
}

}  // namespace
