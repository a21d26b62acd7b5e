// Board files (files/board.hpp): every Raspberry Pi board wires the buttons to the header pins
// its comments say, models select one board each, and bad files get file:line:column and the fix.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "files/board.hpp"

namespace {

using namespace noneuclid;
using files::Board;
using files::BoardError;
using world::Action;

// ---- board files ---------------------------------------------------------------------------

// The Raspberry Pi 40-pin header: physical pin -> BCM GPIO number (-1: power or ground), from
// the Raspberry Pi pinout documentation, written out independently of the board files.
const std::map<int, int> kHeader = {
    {1, -1}, {2, -1}, {3, 2}, {4, -1}, {5, 3}, {6, -1}, {7, 4}, {8, 14}, {9, -1}, {10, 15},
    {11, 17}, {12, 18}, {13, 27}, {14, -1}, {15, 22}, {16, 23}, {17, -1}, {18, 24}, {19, 10}, {20, -1},
    {21, 9}, {22, 25}, {23, 11}, {24, 8}, {25, -1}, {26, 7}, {27, 0}, {28, 1}, {29, 5}, {30, -1},
    {31, 6}, {32, 12}, {33, 13}, {34, -1}, {35, 19}, {36, 16}, {37, 26}, {38, 20}, {39, -1}, {40, 21}};

Board load(const std::string& name) {
    Board b;
    BoardError e;
    EXPECT_TRUE(files::load_board_file(std::string(NONEUCLID_SOURCE_DIR) + "/boards/" + name + ".toml", b, e)) << e.to_string();
    return b;
}

TEST(Boards, EveryPiBoardWiresTheEightButtonsToMatchingHeaderPins) {
    const std::map<std::string, std::string> chip = {{"rpi-zero2w", "pinctrl-bcm2835"}, {"rpi3", "pinctrl-bcm2835"},
                                                     {"rpi4", "pinctrl-bcm2711"}, {"rpi5", "pinctrl-rp1"}};
    for (const auto& [name, label] : chip) {
        SCOPED_TRACE(name);
        const Board b = load(name);
        ASSERT_EQ(b.chips, std::vector<std::string>{label});
        EXPECT_FALSE(b.models.empty());
        int gpio_buttons = 0;
        for (const auto& bb : b.buttons) {
            if (bb.gpio < 0) continue;
            ++gpio_buttons;
            ASSERT_TRUE(kHeader.count(bb.pin)) << "pin " << bb.pin;
            EXPECT_EQ(kHeader.at(bb.pin), bb.gpio) << world::action_name(bb.control) << ": header pin " << bb.pin;
            // Not a pin the usual display/audio HATs or the I2C/SPI/UART defaults take.
            EXPECT_TRUE(bb.gpio != 2 && bb.gpio != 3 && bb.gpio != 14 && bb.gpio != 15) << bb.gpio;
        }
        EXPECT_EQ(gpio_buttons, 8);
        EXPECT_EQ(b.scene, "asteroids");  // the kiosk plays the game
        EXPECT_FALSE(b.sound) << "a kiosk is silent until its board turns the sound on";
        for (Action c : {Action::thrust, Action::left, Action::right, Action::curvature_up, Action::curvature_down,
                          Action::preset, Action::reset, Action::fire}) {
            bool found = false;
            for (const auto& bb : b.buttons) found = found || (bb.control == c && bb.gpio >= 0 && bb.key > 0);
            EXPECT_TRUE(found) << world::action_name(c);
        }
    }
}

// The action table (world/action.hpp) is where an action's keyboard key is: the plain keyboard
// board binds exactly the actions the table gives a key code, and every board that binds a key
// to an action binds the table's.
TEST(Boards, EveryBoardsKeysAreTheActionTables) {
    const Board generic = load("generic");
    std::map<int, int> want, got;  // action -> key code
    for (int i = 0; i < world::kActionCount; ++i)
        if (world::kActions[i].evdev > 0) want[i] = world::kActions[i].evdev;
    for (const auto& bb : generic.buttons) got[static_cast<int>(bb.control)] = bb.key;
    EXPECT_EQ(got, want);
    for (const char* name : {"generic", "rpi-zero2w", "rpi3", "rpi4", "rpi5"}) {
        const Board b = load(name);
        int keys = 0;
        for (const auto& bb : b.buttons) {
            if (bb.key < 0) continue;
            ++keys;
            EXPECT_EQ(bb.key, world::action_row(bb.control).evdev) << name << ": " << world::action_name(bb.control);
        }
        EXPECT_GE(keys, 8) << name;
    }
}

TEST(Boards, TheLanguageIsACodeOrTheLocales) {
    for (auto [text, want] : {std::pair{"[display]\nlanguage = \"fr\"\n", "fr"}, {"[display]\nlanguage = \"de_AT.UTF-8\"\n", "de"},
                              {"[display]\nlanguage = \"\"\n", ""}, {"[display]\n", ""}}) {
        Board b;
        BoardError e;
        ASSERT_TRUE(files::parse_board(text, "t.toml", b, e)) << e.to_string();
        EXPECT_EQ(b.language, want) << text;
    }
}

TEST(Boards, GenericIsKeysOnlyAndMatchesNoModel) {
    const Board b = load("generic");
    EXPECT_FALSE(b.has_gpio());
    EXPECT_TRUE(b.has_keys());
    EXPECT_TRUE(b.models.empty());
}

TEST(Boards, ModelsOfDifferentBoardsDoNotOverlap) {
    // /proc/device-tree/model strings of real boards, and the board each must select.
    const std::map<std::string, std::string> real = {
        {"Raspberry Pi Zero 2 W Rev 1.0", "rpi-zero2w"}, {"Raspberry Pi 3 Model B Plus Rev 1.3", "rpi3"},
        {"Raspberry Pi 4 Model B Rev 1.4", "rpi4"},       {"Raspberry Pi 400 Rev 1.0", "rpi4"},
        {"Raspberry Pi 5 Model B Rev 1.0", "rpi5"},       {"Raspberry Pi Compute Module 4 Rev 1.0", "rpi4"}};
    for (const auto& [model, want] : real) {
        std::vector<std::string> matches;
        for (const char* name : {"rpi-zero2w", "rpi3", "rpi4", "rpi5", "generic"})
            for (const std::string& m : load(name).models)
                if (model.compare(0, m.size(), m) == 0) matches.push_back(name);
        ASSERT_FALSE(matches.empty()) << model;
        // "Raspberry Pi 4" is a prefix of "Raspberry Pi 400": both are rpi4, so only distinct
        // boards count.
        for (const std::string& m : matches) EXPECT_EQ(m, want) << model;
    }
}

struct BadBoard {
    const char* text;
    const char* where;
    const char* message;
};

TEST(Boards, ErrorsNameTheFileThePlaceAndTheFix) {
    const BadBoard cases[] = {
        {"name = \"x\"\ncolour = 3\n", "t.toml:2:1", "unknown key 'colour'"},
        {"[[button]]\naction = \"fly\"\ngpio = 4\n", "t.toml:2:10", "unknown action \"fly\""},
        {"[[button]]\ngpio = 4\n", "t.toml:1:1", "expected action ="},
        {"[[button]]\naction = \"thrust\"\n", "t.toml:1:1", "expected a gpio line or a key code"},
        {"[[button]]\naction = \"thrust\"\ngpio = 4\n[[button]]\naction = \"left\"\ngpio = 4\n", "t.toml:6:8",
         "gpio 4 is already the 'thrust' button"},
        {"[[button]]\naction = \"thrust\"\ngpio = 4000\n", "t.toml:3:8", "'gpio' must be from 0 to 1023"},
        {"[[button]]\naction = \"thrust\"\nkey = 57\npin = 41\n", "t.toml:4:7", "'pin' must be from 1 to 40"},
        {"[display]\nengine = \"quantum\"\n", "t.toml:2:10", "expected engine = \"fixed\""},
        {"[display]\nprojection = \"mercator\"\n", "t.toml:2:14", "expected projection = \"equidistant\""},
        {"[display]\nfps = 0\n", "t.toml:2:7", "'fps' must be from 1 to 1000"},
        {"[display]\npalette = \"sepia\"\n", "t.toml:2:11", "expected palette = \"scene\", \"colour-blind\", \"high-contrast\" or \"print\", found \"sepia\""},
        {"[display]\nlarge_hud = 2\n", "t.toml:2:13", "large_hud"},
        {"[display]\nlanguage = \"es\"\n", "t.toml:2:12", "expected language = en, de or fr (or \"\" for the locale's), found \"es\""},
        {"[display]\none_button = \"yes\"\n", "t.toml:2:14", "one_button"},
        {"[display]\nsound = \"on\"\n", "t.toml:2:9", "sound"},
        {"[gpio]\nchip = 7\n", "t.toml:2:8", "expected a string or a list of strings for 'chip'"},
        {"[attract]\nidle_seconds = -1\n", "t.toml:2:16", "'idle_seconds' must be from 0"},
        {"display = 3\n", "t.toml:1:11", "expected a [display] table"},
        {"name = \n", "t.toml:1:8", "not valid TOML"},
    };
    for (const BadBoard& c : cases) {
        Board b;
        BoardError e;
        ASSERT_FALSE(files::parse_board(c.text, "t.toml", b, e)) << c.text;
        const std::string s = e.to_string();
        EXPECT_NE(s.find(c.where), std::string::npos) << s;
        EXPECT_NE(s.find(c.message), std::string::npos) << s;
    }
    Board b;
    BoardError e;
    EXPECT_FALSE(files::load_board_file("/nonexistent/board.toml", b, e));
    EXPECT_NE(e.to_string().find("the board file: cannot read it"), std::string::npos) << e.to_string();
}

// ---- the board override (/etc/noneuclid/board.toml) ----------------------------------------

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = testing::TempDir() + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// Every field of a board, as text, so that two boards compare in one assertion.
std::string fields(const Board& b) {
    std::string s = b.name + "|" + b.file + "|" + b.device + "|" + std::to_string(b.fps) + "|" + b.scene + "|" + b.engine +
                    "|" + b.projection + "|" + std::to_string(b.antialias) + std::to_string(b.hud) + "|" + b.palette +
                    std::to_string(b.large_hud) + std::to_string(b.one_button) + std::to_string(b.sound) + "|" + b.language + "|" +
                    std::to_string(b.threads) + "|" + std::to_string(b.debounce_ms) + "|" + b.evdev_device + "|" +
                    std::to_string(b.grab) + "|" + std::to_string(b.idle_seconds) + "|" + std::to_string(b.sweep_seconds) + "|" + b.attract_lesson;
    for (const std::string& m : b.models) s += "|model " + m;
    for (const std::string& c : b.chips) s += "|chip " + c;
    for (const auto& bb : b.buttons)
        s += "|" + std::string(world::action_name(bb.control)) + " " + std::to_string(bb.gpio) + " " +
             std::to_string(bb.pin) + " " + std::to_string(bb.key);
    return s;
}

TEST(BoardOverride, TheShippedFileChangesNothingOnAnyBoard) {
    // The Debian package's /etc/noneuclid/board.toml: every setting commented out.
    const std::string shipped = std::string(NONEUCLID_SOURCE_DIR) + "/platform/debian/package/board-override.toml";
    for (const char* name : {"rpi-zero2w", "rpi3", "rpi4", "rpi5", "generic"}) {
        SCOPED_TRACE(name);
        const Board before = load(name);
        Board b = before;
        BoardError e;
        ASSERT_TRUE(files::overlay_board_file(shipped, b, e)) << e.to_string();
        EXPECT_EQ(fields(b), fields(before));
    }
}

TEST(BoardOverride, KeysItSetsReplaceTheBoardsAndTheRestStays) {
    const std::string path = write_file("override_keys.toml",
                                        "[display]\nthreads = 3\nantialias = false\n[attract]\nidle_seconds = 300\n");
    Board b = load("rpi4");
    const Board before = b;
    BoardError e;
    ASSERT_TRUE(files::overlay_board_file(path, b, e)) << e.to_string();
    EXPECT_EQ(b.threads, 3);
    EXPECT_FALSE(b.antialias);
    EXPECT_FALSE(b.sound);
    EXPECT_EQ(b.idle_seconds, 300);
    // Everything else as rpi4.toml has it: set those three back and the boards are the same.
    b.threads = before.threads, b.antialias = before.antialias, b.idle_seconds = before.idle_seconds;
    EXPECT_NE(before.threads, 3);
    EXPECT_TRUE(before.antialias);
    EXPECT_EQ(fields(b), fields(before));
}

TEST(BoardOverride, ItsButtonsReplaceAllOfTheBoards) {
    const std::string path = write_file("override_buttons.toml",
                                        "[gpio]\nchip = [\"/dev/gpiochip1\"]\n"
                                        "[[button]]\naction = \"thrust\"\ngpio = 6\npin = 31\n"
                                        "[[button]]\naction = \"reset\"\ngpio = 17\n");
    Board b = load("rpi4");
    BoardError e;
    ASSERT_TRUE(files::overlay_board_file(path, b, e)) << e.to_string();
    ASSERT_EQ(b.buttons.size(), 2u);
    EXPECT_EQ(b.buttons[0].control, Action::thrust);
    EXPECT_EQ(b.buttons[0].gpio, 6);
    EXPECT_EQ(b.buttons[0].key, -1);
    EXPECT_EQ(b.buttons[1].control, Action::reset);
    EXPECT_EQ(b.buttons[1].gpio, 17);  // rpi4's thrust line: no clash, the board's buttons are gone
    EXPECT_EQ(b.chips, std::vector<std::string>{"/dev/gpiochip1"});
    EXPECT_EQ(b.models, load("rpi4").models);
    EXPECT_EQ(b.file, load("rpi4").file);
}

TEST(BoardOverride, ABadFileIsNamedAndLeavesTheBoardAlone) {
    const std::string path = write_file("override_bad.toml", "[attract]\nidle_seconds = 60\n[display]\nfps = 0\n");
    Board b = load("rpi3");
    const Board before = b;
    BoardError e;
    ASSERT_FALSE(files::overlay_board_file(path, b, e));
    EXPECT_NE(e.to_string().find("override_bad.toml:4:7: display: 'fps' must be from 1 to 1000"), std::string::npos)
        << e.to_string();
    EXPECT_EQ(fields(b), fields(before));
    ASSERT_FALSE(files::overlay_board_file(testing::TempDir(), b, e));
    EXPECT_NE(e.to_string().find("the board override: it is a directory"), std::string::npos) << e.to_string();
}

}  // namespace
