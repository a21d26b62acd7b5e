// Hostile input to the scene and board parsers: text that crashed toml++ (an assertion, or
// undefined behaviour under the sanitizers) gets one sentence with its place; file content in
// a message is quoted (world/quote.hpp): no control character, no byte that is not UTF-8 and no
// more than a line reaches the terminal.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "files/board.hpp"
#include "world/quote.hpp"
#include "files/scene_file.hpp"

namespace {

using namespace noneuclid;
using namespace std::string_literals;
using world::printable;
using world::quote;

// The characters of UTF-8 text (code points), counted independently of quote.cpp's decoder.
std::size_t characters(const std::string& s) {
    std::size_t n = 0;
    for (unsigned char c : s) n += (c & 0xC0) != 0x80;
    return n;
}

// One sentence a terminal shows as it is: no byte below 0x20, no DEL, no ESC, and short.
void expect_one_clean_line(const std::string& s, std::size_t max_bytes = 600) {
    for (unsigned char c : s) {
        EXPECT_FALSE(c < 0x20 || c == 0x7F) << "byte " << int(c) << " in: " << s;
        if (c < 0x20 || c == 0x7F) break;
    }
    EXPECT_TRUE(world::is_plain(s)) << s;
    EXPECT_LE(s.size(), max_bytes) << s.substr(0, 200);
}

// ---- quoting ---------------------------------------------------------------------------------

TEST(Quote, PlainTextIsShownAsItIs) {
    EXPECT_EQ(printable("ship"), "ship");
    EXPECT_EQ(printable("κ-Жé 1.5 #ff4040"), "κ-Жé 1.5 #ff4040");
    EXPECT_EQ(quote("ship"), "'ship'");
    EXPECT_EQ(quote(""), "''");
}

TEST(Quote, ControlCharactersAndBadBytesAreEscaped) {
    EXPECT_EQ(printable("a\x1b[31mb"), "a\\x1b[31mb");
    EXPECT_EQ(printable("a\nb\rc\td"), "a\\x0ab\\x0dc\\x09d");
    EXPECT_EQ(printable("a\0b"s), "a\\x00b");                 // a NUL does not cut the text
    EXPECT_EQ(printable("\x7f"), "\\x7f");
    EXPECT_EQ(printable("a\\x1b"), "a\\\\x1b");              // a backslash in the file is doubled
    EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");           // never UTF-8
    EXPECT_EQ(printable("x\xce"), "x\\xce");                  // a sequence cut at the end
    EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
    EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a UTF-16 surrogate
    EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // above U+10FFFF
    EXPECT_EQ(printable("\xc2\x9b" "2J"), "\\u009b2J");       // C1 CSI, which some terminals obey
    EXPECT_EQ(printable("abc\xe2\x80\xae" "def"), "abc\\u202edef");  // right-to-left override
    EXPECT_EQ(printable("\xe2\x80\xa8"), "\\u2028");          // line separator
    // A library's sentence keeps its own escapes.
    EXPECT_EQ(printable("saw '\\r'", world::kSentenceLimit, false), "saw '\\r'");
    EXPECT_EQ(printable("saw '\x1b'", world::kSentenceLimit, false), "saw '\\x1b'");
}

TEST(Quote, LongTextIsCutAtSixtyCharacters) {
    const std::string mib(1 << 20, 'a');
    EXPECT_EQ(printable(mib), std::string(59, 'a') + "…");
    EXPECT_EQ(printable(std::string(60, 'a')), std::string(60, 'a'));  // fits: whole
    EXPECT_EQ(printable(std::string(61, 'a')), std::string(59, 'a') + "…");
    // An escape is not cut: 58 + 4 characters do not fit, so the escape goes whole.
    EXPECT_EQ(printable(std::string(58, 'a') + "\x1b" + "bbbb"), std::string(58, 'a') + "…");
    // Nor is a UTF-8 sequence: 100 two-byte characters give 59 of them and the ellipsis.
    std::string zh;
    for (int i = 0; i < 100; ++i) zh += "Ж";
    std::string want;
    for (int i = 0; i < 59; ++i) want += "Ж";
    EXPECT_EQ(printable(zh), want + "…");
    EXPECT_EQ(characters(printable(zh)), 60u);
    std::string esc;
    for (int i = 0; i < 1000; ++i) esc += "\x1b";
    EXPECT_LE(characters(printable(esc)), 60u);
    EXPECT_EQ(quote(mib), "'" + std::string(59, 'a') + "…'");
}

// ---- text that toml++ 3.3.0 and 3.4.0 cannot take ------------------------------------------

struct Hostile {
    std::string text;
    long line, column;  // where the sentence must point, counted by hand
    const char* says;
};

// Every input here crashed or hit undefined behaviour in toml++ (3.3.0 and 3.4.0) under the
// sanitizer build, or is a byte TOML does not allow in a file.
const Hostile kHostile[] = {
    {"κ = 0.5\n", 1, 1, "the character 'κ' (U+03BA) outside quotes"},
    {"été = 1\n", 1, 1, "the character 'é' (U+00E9) outside quotes"},
    {"x = Ж\n", 1, 5, "the character 'Ж' (U+0416) outside quotes"},
    {"curvature = 0.5 ¡\n", 1, 17, "the character '¡' (U+00A1) outside quotes"},
    {"[\r", 1, 2, "a carriage return (\\x0d) not followed by a line feed"},
    {"[[\r", 1, 3, "a carriage return"},
    {"a = 1\r", 1, 6, "a carriage return"},
    // A table header whose name does not start with a key's character (found by fuzz_scene).
    {"[*[", 1, 1, "expected a table's name after '[', found '*'"},
    {"[[#rid]]\nkind = \"axes\"\n", 1, 1, "expected a table's name after '[[', found '#'"},
    {"[\n", 1, 1, "expected a table's name after '[', found the end of the line"},
    {"a = 1\n  [\r\n", 2, 3, "expected a table's name after '[', found the end of the line"},
    {"[[ [a]]\n", 1, 1, "expected a table's name after '[[', found '['"},
    {"[ =", 1, 1, "expected a table's name after '[', found '='"},
    {"[a] [Ж]\n", 1, 5, "expected a table's name after '[', found 'Ж'"},
    {"[[", 1, 1, "expected a table's name after '[[', found the end of the file"},
    // A quote inside a bad token does not start a string: toml++ reads the token on (fuzz_board).
    {"s =+~achipn\"proj\xcc\xaa", 1, 17, "(U+032A) outside quotes"},
    {"Ysname  =+z\"\xef\xba\xbf\"\\U= ]\naccut", 1, 13, "(U+FEBF) outside quotes"},
    // A backslash before a non-ASCII character in a basic string (fuzz_board).
    {"\"\"\"gpiz]\n\\\xd0\x96\"]", 2, 2, "the character 'Ж' (U+0416) after a backslash"},
    {"s = \"a\\\xc2\xa7\"", 1, 8, "the character '§' (U+00A7) after a backslash"},
    // A date without a time after its separator (fuzz_scene, and by hand).
    {"s =1979-05-27Tfacin:00Z", 1, 4, "expected a date and a time (YYYY-MM-DDTHH:MM:SS), found '1979-05-27T'"},
    {"s = 1979-05-27tz:", 1, 5, "found '1979-05-27t'"},
    {"s = 1979-05-27 1\n", 1, 5, "found '1979-05-27 1'"},
    {"s = [1979-05-27 1]\n", 1, 6, "found '1979-05-27 1'"},
    {"s = [\n 1, 1979-05-27 1,\n]", 2, 5, "found '1979-05-27 1'"},
    {"e = 1979-02-PH 9 1979-02,P]litcacing2\n", 1, 5, "found '1979-02-PH 9'"},
    {"s = 1979-05-R_s 2 =0= +\\+ ", 1, 5, "found '1979-05-R_s 2'"},
    // Brackets inside a bad token are not an array's or a table's (fuzz_board, fuzz_scene).
    {"sn= [[-Y[\"\xcf\xbb:bn=s7:3", 1, 11, "(U+03FB) outside quotes"},
    {"s =0x000000000v08{{\"hi\xc2\xb0] from", 1, 23, "(U+00B0) outside quotes"},
    // A '}' where an array expects a value: an assertion in toml++ (fuzz_world).
    {"a = [[1], }\n", 1, 11, "'}' closes an array, which ']' closes"},
    {"a = {b = [1]]\n", 1, 13, "']' closes an inline table, which '}' closes"},
    {"\xcc\xaa", 1, 1, "(U+032A) outside quotes"},            // upstream issue 295's input
    {"# ok\n、 = 1\n", 2, 1, "(U+3001) outside quotes"},      // CJK punctuation
    {"a = 1 \xe3\x80\x80\n", 1, 7, "(U+3000) outside quotes"},  // ideographic space
    {"a = 1\n\xef\xbb\xbf" "b = 2\n", 2, 1, "(U+FEFF) outside quotes"},  // a BOM not at the start
    {"s = \"\"\"\\\n\xc2\xa7\"\"\"\n", 2, 1, "right after a line-ending backslash: write it as an escape, \\u00A7"},
    {"s = \"\"\"\\   \r\n  \n  \xe3\x80\x81\"\"\"\n", 3, 3, "right after a line-ending backslash"},
    {"s = \"\\ \xc2\xa7\"\n", 1, 8, "right after a line-ending backslash"},
    {"name = \"ok\"\n\xff\n", 2, 1, "the byte \\xff is not UTF-8"},
    {"name = \"\xc3\x28\"\n", 1, 9, "the byte \\xc3 is not UTF-8"},
    {"name = \"a\0b\"\n"s, 1, 10, "the control character \\x00"},
    {"# \x1b[2J\n", 1, 3, "the control character \\x1b"},
    {"name = \"\x1b]0;pwned\x07\"\n", 1, 9, "the control character \\x1b"},
    {"a = 1\x7f\n", 1, 6, "the control character \\x7f"},
    {"a = \"\"\"x\x0by\"\"\"\n", 1, 9, "the control character \\x0b"},
};

TEST(HostileToml, EveryInputGetsOneSentenceWithItsPlaceInScenesAndBoards) {
    for (const Hostile& h : kHostile) {
        SCOPED_TRACE(printable(h.text));
        world::Scene s;
        files::SceneError e;
        ASSERT_FALSE(files::parse_scene(h.text, "t.toml", s, e));
        const std::string where = "t.toml:" + std::to_string(h.line) + ":" + std::to_string(h.column) + ": not valid TOML: ";
        EXPECT_EQ(e.to_string().rfind(where, 0), 0u) << e.to_string();
        EXPECT_NE(e.message.find(h.says), std::string::npos) << e.to_string();
        expect_one_clean_line(e.to_string());
        files::Board b;
        files::BoardError be;
        ASSERT_FALSE(files::parse_board(h.text, "t.toml", b, be));
        EXPECT_EQ(be.to_string(), e.to_string());
    }
}

// What the check lets through is what TOML allows: non-ASCII text in strings and comments, a
// byte-order mark at the start, CR LF line ends, line-ending backslashes, quotes inside strings.
TEST(HostileToml, TomlThatIsFineStillLoads) {
    const std::string text =
        "\xef\xbb\xbf# Ж été κ 、 \xe3\x80\x80 ¡\r\n"
        "curvature = 0.5 # ¡\r\n"
        "[[body]]\r\n"
        "name = \"κ-ship \\\"Ж\\\" 'x' # not a comment\"\r\n"
        "vertices = [[0.1, 0.0], [0.1, 120.0], [0.1, 240.0]]\r\n"
        "[[body]]\n"
        "name = \"\"\"line \\\n   continued \"quoted\" été\"\"\"\n"
        "color = '#00ff00'\n"
        "vertices = [[0.2, 0.0]] # ''' \"\"\" é\n"
        "[[body]]\n"
        "name = '''é\n'l' ''\"'''\n"
        "vertices = [\n  [0.2, 0.0], # a comment [*\n  [0.3, 90.0],\n]\n"
        "[[ grid ]]\n"
        "kind = \"radial\"\n"
        "1979-05-27tz = 1979-05-27T07:32:00Z\n"  // a bare key may look like a date
        "a = [1979-05-27, 1979-05-27 07:32:00, 07:32:00]\n"
        "[ \"grid\" . \"\" ]\n"  // not a scene's key: refused by the scene's reader, not by the guard
        ;
    world::Scene s;
    files::SceneError e;
    ASSERT_FALSE(files::parse_scene(text, "fine.toml", s, e));
    // Refused by the scene's reader (no such keys in a grid), not by the guard or toml++.
    EXPECT_NE(e.to_string().find(": grid: unknown key '"), std::string::npos) << e.to_string();
    ASSERT_TRUE(files::parse_scene(text.substr(0, text.rfind("1979-05-27tz")), "fine.toml", s, e)) << e.to_string();
    EXPECT_EQ(s.curvature, 0.5);
    ASSERT_EQ(s.bodies.size(), 12u + 3u);  // the radial grid's lines, then the bodies
    const world::SceneBody* b = &s.bodies[12];
    EXPECT_EQ(b[0].name, "κ-ship \"Ж\" 'x' # not a comment");
    EXPECT_EQ(b[0].vertices.size(), 3u);
    EXPECT_EQ(b[1].name, "line continued \"quoted\" été");
    EXPECT_EQ(b[1].color, (world::Rgb{0, 255, 0}));
    EXPECT_EQ(b[2].name, "é\n'l' ''\"");
    EXPECT_EQ(b[2].vertices.size(), 2u);
}

// ---- file content in messages ----------------------------------------------------------------

struct Echo {
    std::string text;
    std::string shows;  // what the sentence shows of the file, escaped
};

TEST(Messages, SceneFileContentIsQuotedEscapedAndShort) {
    const std::string mib(1 << 20, 'k');
    const Echo cases[] = {
        // A body name with an ESC sequence, in the context of a later error.
        {"[[body]]\nname = \"a\\u001b[31mb\"\nspeed = 1\nvertices = [[0.1, 0]]\n", "body 'a\\x1b[31mb': unknown key 'speed'"},
        // A key with a newline, and one with a NUL: the sentence goes on after it.
        {"\"x\\ny\" = 1\n", "unknown key 'x\\x0ay' (expected one of"},
        {"\"x\\u0000y\" = 1\n", "unknown key 'x\\x00y' (expected one of"},
        // A 1 MiB key.
        {"\"" + mib + "\" = 1\n", "unknown key '" + std::string(59, 'k') + "…' (expected one of"},
        // Bad values.
        {"[[grid]]\nkind = \"\\u001b[2J\"\n", "found \"\\x1b[2J\""},
        {"[[body]]\ncolor = \"\\u009b31m\"\nvertices = [[0.1, 0]]\n", "found \"\\u009b31m\""},
        {"[[grid]]\nkind = \"" + mib + "\"\n", "found \"" + std::string(59, 'k') + "…\""},
        // toml++'s own sentences about a key given twice: it escapes the ESC itself, and its
        // sentence is cut like ours.
        {"\"\\u001b[2J\" = 1\n\"\\u001b[2J\" = 2\n", "m.toml:2:15: not valid TOML: Error while parsing key-value pair: cannot redefine"},
        {"\"" + mib + "\" = 1\n\"" + mib + "\" = 2\n", "cannot redefine existing integer '\"" + std::string(60, 'k')},
    };
    for (const Echo& c : cases) {
        SCOPED_TRACE(printable(c.text));
        world::Scene s;
        files::SceneError e;
        ASSERT_FALSE(files::parse_scene(c.text, "m.toml", s, e));
        EXPECT_NE(e.to_string().find(c.shows), std::string::npos) << e.to_string();
        expect_one_clean_line(e.to_string());
    }
    // The file's name too: it may come from a file (a board's scene, a recording's).
    world::Scene s;
    files::SceneError e;
    EXPECT_FALSE(files::load_scene_file("/nonexistent/\x1b[2J.toml", s, e));
    EXPECT_EQ(e.to_string().rfind("/nonexistent/\\x1b[2J.toml: the scene file: cannot read it", 0), 0u) << e.to_string();
    expect_one_clean_line(e.to_string());
}

TEST(Messages, BoardFileContentIsQuotedAndItsNamesArePlain) {
    const Echo cases[] = {
        {"[display]\nengine = \"\\u001b[2J\"\n", "found \"\\x1b[2J\""},
        {"[display]\nprojection = \"a\\nb\"\n", "found \"a\\x0ab\""},
        {"[[button]]\naction = \"\\u001b\"\ngpio = 4\n", "unknown action \"\\x1b\""},
        {"\"\\u001b\" = 1\n", "unknown key '\\x1b'"},
        // Strings that other messages show as they are (a device, a chip, a scene's path) must
        // hold no control character.
        {"[display]\ndevice = \"/dev/fb0\\u001b[2J\"\n", "display: expected 'device' without control characters, found '/dev/fb0\\x1b[2J'"},
        {"[display]\nscene = \"a\\u0000b\"\n", "display: expected 'scene' without control characters, found 'a\\x00b'"},
        {"[evdev]\ndevice = \"\\n\"\n", "evdev: expected 'device' without control characters"},
        {"[gpio]\nchip = [\"ok\", \"\\u001b\"]\n", "gpio: expected 'chip' without control characters, found '\\x1b'"},
        {"[gpio]\nchip = \"\\u202e\"\n", "found '\\u202e'"},
        {"name = \"\\u0007\"\n", "expected 'name' without control characters"},
        {"models = [\"Pi\\r\"]\n", "expected 'models' without control characters"},
    };
    for (const Echo& c : cases) {
        SCOPED_TRACE(printable(c.text));
        files::Board b;
        files::BoardError e;
        ASSERT_FALSE(files::parse_board(c.text, "b.toml", b, e));
        EXPECT_NE(e.to_string().find(c.shows), std::string::npos) << e.to_string();
        expect_one_clean_line(e.to_string());
    }
    files::Board b;
    files::BoardError e;
    ASSERT_TRUE(files::parse_board("name = \"Pi été\"\n[display]\ndevice = \"/dev/fb1\"\n", "b.toml", b, e)) << e.to_string();
    EXPECT_EQ(b.name, "Pi été");
}

}  // namespace
