// Actions files and recordings (app/script.hpp): events and settings parsed, errors with their
// line; the settings layered under the command line (app/options.hpp).
#include <gtest/gtest.h>

#include <string>

using namespace std::string_literals;

#include "app/options.hpp"
#include "app/script.hpp"
#include "world/quote.hpp"

namespace {

using namespace noneuclid;
using app::Script;
using app::ScriptError;
using app::ScriptEvent;
using world::Action;

TEST(Script, EventsParseSortedWithTheirKinds) {
    Script s;
    ScriptError err;
    ASSERT_TRUE(app::parse_script("# comment\n1.5 release thrust\n0 press thrust  # go\n\n2 tap preset\n"
                                  "2 tap projection\n0.75 press spherical\n3.5 attract on\n4 attract off\n",
                                  "a.txt", s, err))
        << err.to_string();
    ASSERT_EQ(s.events.size(), 7u);
    EXPECT_EQ(s.events[0].time, 0.0);  // sorted by time
    EXPECT_EQ(s.events[0].kind, ScriptEvent::press);
    EXPECT_EQ(s.events[1].control, Action::spherical);
    EXPECT_EQ(s.events[2].kind, ScriptEvent::release);
    EXPECT_EQ(s.events[3].control, Action::preset);  // ties keep the file's order
    EXPECT_EQ(s.events[4].control, Action::projection);
    EXPECT_EQ(s.events[5].kind, ScriptEvent::attract_on);
    EXPECT_EQ(s.events[6].kind, ScriptEvent::attract_off);
    EXPECT_TRUE(s.settings.empty());
}

TEST(Script, SettingsKeepTheirLineAndValue) {
    Script s;
    ScriptError err;
    ASSERT_TRUE(app::parse_script("scene /tmp/my scene.toml\nhud off\n0 press thrust\nsize 320x200\n", "r.txt", s, err));
    ASSERT_EQ(s.settings.size(), 3u);
    EXPECT_EQ(s.settings[0].key, "scene");
    EXPECT_EQ(s.settings[0].value, "/tmp/my scene.toml");
    EXPECT_EQ(s.settings[1].line, 2);
    EXPECT_EQ(s.settings[2].value, "320x200");
    EXPECT_EQ(s.events.size(), 1u);
}

TEST(Script, ErrorsNameTheLineAndWhatWasExpected) {
    struct Case {
        const char* text;
        long line;
        const char* says;
    };
    const Case cases[] = {
        {"0 press thrust\nsoon press thrust\n", 2, "expected a time in seconds (a number >= 0) or a setting"},
        {"1 push thrust\n", 1, "expected press, release, tap, mark or attract after the time, found 'push'"},
        {"1 mark 1\n", 1, "expected 'mark R THETA'"},
        {"1 mark -1 30\n", 1, "expected 'mark R THETA'"},
        {"1 mark 1 north\n", 1, "expected 'mark R THETA'"},
        {"1 mark 1 30 40\n", 1, "unexpected '40'"},
        {"1 press warp\n", 1, "found 'warp'"},
        {"1 press quit\n", 1, "found 'quit'"},  // quitting is not replayed
        {"1 press thrust now\n", 1, "unexpected 'now'"},
        {"1 attract maybe\n", 1, "expected on or off after 'attract'"},
        {"-1 press thrust\n", 1, "a number >= 0"},
        {"hud\n", 1, "the setting 'hud' needs a value"},
    };
    for (const Case& c : cases) {
        Script s;
        ScriptError err;
        EXPECT_FALSE(app::parse_script(c.text, "a.txt", s, err)) << c.text;
        EXPECT_EQ(err.line, c.line) << c.text;
        EXPECT_NE(err.to_string().find(c.says), std::string::npos) << err.to_string();
        EXPECT_EQ(err.to_string().rfind("a.txt:" + std::to_string(c.line) + ": ", 0), 0u) << err.to_string();
    }
    Script s;
    ScriptError err;
    EXPECT_FALSE(app::load_script("/nonexistent/actions.txt", s, err));
    EXPECT_NE(err.to_string().find("cannot read"), std::string::npos);
}

// An editor's UTF-8 byte-order mark before the first line, as scene files allow it.
TEST(Script, AByteOrderMarkBeforeTheFirstLineIsAccepted) {
    Script s;
    ScriptError err;
    ASSERT_TRUE(app::parse_script("\xEF\xBB\xBFscene kiosk\r\n0.5 press thrust\r\n", "bom.txt", s, err)) << err.to_string();
    ASSERT_EQ(s.settings.size(), 1u);
    EXPECT_EQ(s.settings[0].key, "scene");
    EXPECT_EQ(s.settings[0].value, "kiosk");
    ASSERT_EQ(s.events.size(), 1u);
    EXPECT_EQ(s.events[0].time, 0.5);
    ASSERT_TRUE(app::parse_script("\xEF\xBB\xBF" "1 tap preset\n", "bom.txt", s, err)) << err.to_string();
    EXPECT_EQ(s.events.size(), 1u);
    // Only at the start: elsewhere it is a bad token like any other, and shown escaped.
    ASSERT_FALSE(app::parse_script("0 press thrust\n\xEF\xBB\xBF" "1 tap preset\n", "bom.txt", s, err));
    EXPECT_EQ(err.to_string(), "bom.txt:2: expected a time in seconds (a number >= 0) or a setting (scene, curvature, engine, "
                               "projection, size, format, aa, hud, font, legend, frames, best, centre, view, tissot, palette, large-hud, hud-scale, lang) first, found '\\ufeff1'");
}

// What the file holds reaches the message escaped (world/quote.hpp) and cut to 60 characters.
TEST(Script, FileContentInMessagesIsQuoted) {
    struct Case {
        std::string text;
        std::string message;  // the whole sentence after "q.txt:1: "
    };
    const std::string mib(1 << 20, 'w');
    const Case cases[] = {
        {"1 press \x1b[2Jwarp\n", "expected a control (thrust, left, right, curvature_up, curvature_down, preset, reset, "
                                  "hyperbolic, flat, spherical, fire, instrument, strength_up, strength_down, pitch_up, pitch_down, roll_left, roll_right, projection, hud, mute), found '\\x1b[2Jwarp'"},
        {"1 press w\0arp now\n"s, "expected a control (thrust, left, right, curvature_up, curvature_down, preset, reset, "
                                  "hyperbolic, flat, spherical, fire, instrument, strength_up, strength_down, pitch_up, pitch_down, roll_left, roll_right, projection, hud, mute), found 'w\\x00arp'"},
        {"1 \x9b\xff thrust\n", "expected press, release, tap, mark or attract after the time, found '\\x9b\\xff'"},
        {"1 attract \xc2\x9b" "31m\n", "expected on or off after 'attract', found '\\u009b31m'"},
        {"1 press thrust \x1b\n", "unexpected '\\x1b' after 'thrust'"},
        {mib + " press thrust\n", "expected a time in seconds (a number >= 0) or a setting (scene, curvature, engine, "
                                  "projection, size, format, aa, hud, font, legend, frames, best, centre, view, tissot, palette, large-hud, hud-scale, lang) first, found '" +
                                      std::string(59, 'w') + "…'"},
        {"scene a\x1b]0;x\x07" "b\n", "the setting 'scene' has a control character or a byte that is not UTF-8: "
                                  "'a\\x1b]0;x\\x07b'"},
        {"font \xff.psf\n", "the setting 'font' has a control character or a byte that is not UTF-8: '\\xff.psf'"},
        {"scene " + mib + "\n", "the setting 'scene' is 1048576 bytes long, over the 4096 a value may have: '" +
                                     std::string(59, 'w') + "…'"},
    };
    for (const Case& c : cases) {
        Script s;
        ScriptError err;
        ASSERT_FALSE(app::parse_script(c.text, "q.txt", s, err)) << c.text.substr(0, 80);
        EXPECT_EQ(err.to_string(), "q.txt:1: " + c.message);
    }
    // A path of PATH_MAX bytes is still a setting.
    Script s;
    ScriptError err;
    const std::string path = "/" + std::string(4095, 'p');
    ASSERT_TRUE(app::parse_script("scene " + path + "\n", "q.txt", s, err)) << err.to_string().substr(0, 200);
    EXPECT_EQ(s.settings.at(0).value, path);
    // The file's own name, which came from the command line, is shown escaped too.
    EXPECT_FALSE(app::load_script("/nonexistent/\x1b[2J.txt", s, err));
    EXPECT_EQ(err.to_string().rfind("/nonexistent/\\x1b[2J.txt: the actions file: cannot read it", 0), 0u) << err.to_string();
}

// An event's time is its whole first word, a decimal number: a NUL or another control byte in it
// (where strtod would stop and take what came before) is refused, and so is a control byte
// that a reader splitting on any white space would take for a space between the words.
TEST(Script, AControlByteInAnEventIsRefusedNotReadPast) {
    struct Case {
        std::string text;
        std::string message;  // the whole sentence after "c.txt:1: "
    };
    const std::string expected_time = "expected a time in seconds (a number >= 0) or a setting (scene, curvature, engine, "
                                      "projection, size, format, aa, hud, font, legend, frames, best, centre, view, tissot, palette, large-hud, hud-scale, lang) first, found ";
    const Case cases[] = {
        {"1.5\0 press thrust\n"s, expected_time + "'1.5\\x00'"},
        {"1.5\0junk press thrust\n"s, expected_time + "'1.5\\x00junk'"},
        {"\0 press thrust\n"s, expected_time + "'\\x00'"},
        {"1\x01 press thrust\n", expected_time + "'1\\x01'"},
        {"2\x1b[31m press thrust\n", expected_time + "'2\\x1b[31m'"},
        {"3\x7f press thrust\n", expected_time + "'3\\x7f'"},
        {"0x1p3 press thrust\n", expected_time + "'0x1p3'"},  // a decimal number, not C's hexadecimal
        {"1.5\vpress thrust\n", "a control character ('\\x0b') where only spaces and tabs may part words: '1.5\\x0bpress thrust'"},
        {"1.5 press\fthrust\n", "a control character ('\\x0c') where only spaces and tabs may part words: '1.5 press\\x0cthrust'"},
        {"1.5 press\rthrust\n", "a control character ('\\x0d') where only spaces and tabs may part words: '1.5 press\\x0dthrust'"},
        {"\x0bscene kiosk\n", "a control character ('\\x0b') where only spaces and tabs may part words: '\\x0bscene kiosk'"},
        {"\x0c\n", "a control character ('\\x0c') where only spaces and tabs may part words: '\\x0c'"},
    };
    for (const Case& c : cases) {
        Script s;
        ScriptError err;
        ASSERT_FALSE(app::parse_script(c.text, "c.txt", s, err)) << world::printable(c.text, 80);
        EXPECT_EQ(err.to_string(), "c.txt:1: " + c.message);
    }
    // What stays accepted: decimal times of every spelling, tabs between words, CR LF line ends,
    // and any bytes in a comment.
    Script s;
    ScriptError err;
    ASSERT_TRUE(app::parse_script("0 press thrust\r\n.5\trelease thrust\n1e0 tap preset # \x01\x1b\n2.25E+0 tap hud\n"s,
                                  "c.txt", s, err))
        << err.to_string();
    ASSERT_EQ(s.events.size(), 4u);
    EXPECT_EQ(s.events[1].time, 0.5);
    EXPECT_EQ(s.events[2].time, 1.0);
    EXPECT_EQ(s.events[3].time, 2.25);
}

TEST(Script, ThePlayerGivesEventsWhenDue) {
    Script s;
    ScriptError err;
    ASSERT_TRUE(app::parse_script("0.1 press thrust\n0.100000000 release thrust\n0.2 press left\n", "p", s, err));
    app::ScriptPlayer p(s.events);
    EXPECT_EQ(p.next_due(0.05), nullptr);
    EXPECT_NE(p.next_due(0.1 - 5e-10), nullptr);  // within the 1e-9 s the times are printed to
    EXPECT_NE(p.next_due(0.1), nullptr);
    EXPECT_EQ(p.next_due(0.19), nullptr);
    EXPECT_EQ(p.next_due(0.2)->control, Action::left);
    EXPECT_EQ(p.next_due(100), nullptr);
}

// A recording's settings lie under the command line: the defaults, then the file, then argv.
TEST(Options, SettingsAreDefaultsUnderTheCommandLine) {
    const std::string path = ::testing::TempDir() + "Options.SettingsAreDefaultsUnderTheCommandLine.txt";
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("scene fig14\nengine double\nprojection lambert\nhud on\naa on\nsize 320x200\nframes 42\n"
                   "legend keys\n0 press thrust\n", f);
        std::fclose(f);
    }
    std::string a0 = "noneuclid", a1 = "--actions", a2 = path, a3 = "--engine", a4 = "float", a5 = "--no-hud";
    char* argv[] = {a0.data(), a1.data(), a2.data(), a3.data(), a4.data(), a5.data()};
    Script script;
    const app::Options o = app::layered_options(6, argv, 1, app::Command::render, script);
    EXPECT_EQ(o.scene, "fig14");
    EXPECT_EQ(o.engine, world::engine_named("float"));  // the command line wins
    EXPECT_EQ(o.projection, geo::Projection::lambert_equal_area);
    EXPECT_FALSE(o.hud);  // --no-hud wins over "hud on"
    EXPECT_TRUE(o.aa);
    EXPECT_EQ(o.width, 320);
    EXPECT_EQ(o.height, 200);
    EXPECT_EQ(o.frames, 42);
    EXPECT_EQ(o.legend, "keys");
    EXPECT_EQ(script.events.size(), 1u);
    // dump has no HUD: the setting does not matter to it, and is no error.
    Script s2;
    const app::Options d = app::layered_options(3, argv, 1, app::Command::dump, s2);
    EXPECT_EQ(d.engine, world::engine_named("double"));
}

TEST(Options, ABadSettingNamesTheFileAndLine) {
    const std::string path = ::testing::TempDir() + "Options.ABadSettingNamesTheFileAndLine.txt";
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("scene kiosk\n\nengine quantum\n", f);
        std::fclose(f);
    }
    std::string a0 = "noneuclid", a1 = "--actions", a2 = path;
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    Script script;
    try {
        app::layered_options(3, argv, 1, app::Command::render, script);
        ADD_FAILURE() << "no error";
    } catch (const app::UsageError& e) {
        EXPECT_EQ(e.message, path + ":3: --engine must be fixed, double, float or paper, not 'quantum'.");
    }
}

// The earth scene's centre and view are settings too: a recording of it replays the same place
// and zoom (app/setup.cpp writes them), and a bad one names the file and line.
TEST(Options, TheEarthsCentreAndViewAreSettings) {
    const std::string path = ::testing::TempDir() + "Options.TheEarthsCentreAndViewAreSettings.txt";
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("scene earth\ncentre -33.9,151.2\nview 1500\n", f);
        std::fclose(f);
    }
    std::string a0 = "noneuclid", a1 = "--actions", a2 = path;
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    Script script;
    const app::Options o = app::layered_options(3, argv, 1, app::Command::render, script);
    EXPECT_EQ(o.params.centre_lat, -33.9);
    EXPECT_EQ(o.params.centre_lon, 151.2);
    EXPECT_EQ(o.params.view_km, 1500);
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("scene earth\ncentre 100,0\n", f);
        std::fclose(f);
    }
    Script s2;
    try {
        app::layered_options(3, argv, 1, app::Command::render, s2);
        ADD_FAILURE() << "no error";
    } catch (const app::UsageError& e) {
        EXPECT_NE(e.message.find(path + ":2: --centre must be a latitude and a longitude"), std::string::npos) << e.message;
    }
}

}  // namespace
