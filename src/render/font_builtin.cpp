// The built-in font: 6x8 cells drawn as text below, ASCII and the Latin-1 letters German and
// French need, turned into a bitmap table at compile time (no start-up code, no heap).
#include <array>
#include <cstdint>
#include <string_view>

#include "render/font.hpp"

namespace noneuclid::render {

namespace {

// ---------------------------------------------------------------------------------------------
// The built-in font, drawn here ('#' set, '.' clear), 12 glyphs to a block in code point order,
// one space between glyphs. Rows 0..6 hold the glyph (capitals and digits 7 rows tall, lowercase
// x-height rows 2..6, baseline row 6); row 7 only the descenders of g j p q y and the comma.
// Turned into the bitmap table at compile time; a malformed drawing does not compile.
// ---------------------------------------------------------------------------------------------
constexpr int kCellWidth = 6, kCellHeight = 8, kBuiltinGlyphs = 256;

struct ArtBlock {
    char32_t first;
    int count;
    const char* rows[kCellHeight];
};

// clang-format off
constexpr ArtBlock kArt[] = {
    //   ' '   !     "     #     $     %     &     '     (     )     *     +
    {32, 12, {"..... ..#.. .#.#. .#.#. ..#.. ##... .##.. ..#.. ...#. .#... ..... .....",
              "..... ..#.. .#.#. .#.#. .#### ##..# #..#. ..#.. ..#.. ..#.. ..#.. ..#..",
              "..... ..#.. ..... ##### #.#.. ...#. #.#.. ..... .#... ...#. #.#.# ..#..",
              "..... ..#.. ..... .#.#. .###. ..#.. .#... ..... .#... ...#. .###. #####",
              "..... ..#.. ..... ##### ..#.# .#... #.#.# ..... .#... ...#. #.#.# ..#..",
              "..... ..... ..... .#.#. ####. #..## #..#. ..... ..#.. ..#.. ..#.. ..#..",
              "..... ..#.. ..... .#.#. ..#.. ...## .##.# ..... ...#. .#... ..... .....",
              "..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ....."}},
    //   ,     -     .     /     0     1     2     3     4     5     6     7
    {44, 12, {"..... ..... ..... ..... .###. ..#.. .###. ##### ...#. ##### ..##. #####",
              "..... ..... ..... ....# #...# .##.. #...# ...#. ..##. #.... .#... ....#",
              "..... ..... ..... ...#. #..## ..#.. ....# ..#.. .#.#. ####. #.... ...#.",
              "..... ##### ..... ..#.. #.#.# ..#.. ...#. ...#. #..#. ....# ####. ..#..",
              "..... ..... ..... .#... ##..# ..#.. ..#.. ....# ##### ....# #...# .#...",
              ".##.. ..... .##.. #.... #...# ..#.. .#... #...# ...#. #...# #...# .#...",
              "..#.. ..... .##.. ..... .###. .###. ##### .###. ...#. .###. .###. .#...",
              ".#... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ....."}},
    //   8     9     :     ;     <     =     >     ?     @     A     B     C
    {56, 12, {".###. .###. ..... ..... ...#. ..... .#... .###. .###. .###. ####. .###.",
              "#...# #...# .##.. .##.. ..#.. ..... ..#.. #...# #...# #...# #...# #...#",
              "#...# #...# .##.. .##.. .#... ##### ...#. ....# #.### #...# #...# #....",
              ".###. .#### ..... ..... #.... ..... ....# ...#. #.#.# ##### ####. #....",
              "#...# ....# .##.. .##.. .#... ##### ...#. ..#.. #.### #...# #...# #....",
              "#...# ...#. .##.. ..#.. ..#.. ..... ..#.. ..... #.... #...# #...# #...#",
              ".###. .##.. ..... .#... ...#. ..... .#... ..#.. .#### #...# ####. .###.",
              "..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ....."}},
    //   D     E     F     G     H     I     J     K     L     M     N     O
    {68, 12, {"###.. ##### ##### .###. #...# .###. ..### #...# #.... #...# #...# .###.",
              "#..#. #.... #.... #...# #...# ..#.. ...#. #..#. #.... ##.## #...# #...#",
              "#...# #.... #.... #.... #...# ..#.. ...#. #.#.. #.... #.#.# ##..# #...#",
              "#...# ####. ####. #.### ##### ..#.. ...#. ##... #.... #.#.# #.#.# #...#",
              "#...# #.... #.... #...# #...# ..#.. ...#. #.#.. #.... #...# #..## #...#",
              "#..#. #.... #.... #...# #...# ..#.. #..#. #..#. #.... #...# #...# #...#",
              "###.. ##### #.... .#### #...# .###. .##.. #...# ##### #...# #...# .###.",
              "..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ....."}},
    //   P     Q     R     S     T     U     V     W     X     Y     Z     [
    {80, 12, {"####. .###. ####. .#### ##### #...# #...# #...# #...# #...# ##### .###.",
              "#...# #...# #...# #.... ..#.. #...# #...# #...# #...# #...# ....# .#...",
              "#...# #...# #...# #.... ..#.. #...# #...# #...# .#.#. .#.#. ...#. .#...",
              "####. #...# ####. .###. ..#.. #...# #...# #.#.# ..#.. ..#.. ..#.. .#...",
              "#.... #.#.# #.#.. ....# ..#.. #...# #...# #.#.# .#.#. ..#.. .#... .#...",
              "#.... #..#. #..#. ....# ..#.. #...# .#.#. #.#.# #...# ..#.. #.... .#...",
              "#.... .##.# #...# ####. ..#.. .###. ..#.. .#.#. #...# ..#.. ##### .###.",
              "..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ....."}},
    //   \     ]     ^     _     `     a     b     c     d     e     f     g
    {92, 12, {"..... .###. ..#.. ..... .#... ..... #.... ..... ....# ..... ..##. .....",
              "#.... ...#. .#.#. ..... ..#.. ..... #.... ..... ....# ..... .#..# .....",
              ".#... ...#. #...# ..... ..... .###. #.##. .###. .##.# .###. .#... .####",
              "..#.. ...#. ..... ..... ..... ....# ##..# #.... #..## #...# ###.. #...#",
              "...#. ...#. ..... ..... ..... .#### #...# #.... #...# ##### .#... #...#",
              "....# ...#. ..... ..... ..... #...# #...# #...# #...# #.... .#... .####",
              "..... .###. ..... ##### ..... .#### ####. .###. .#### .###. .#... ....#",
              "..... ..... ..... ..... ..... ..... ..... ..... ..... ..... ..... .###."}},
    //   h     i     j     k     l     m     n     o     p     q     r     s
    {104, 12, {"#.... ..#.. ...#. #.... .##.. ..... ..... ..... ..... ..... ..... .....",
               "#.... ..... ..... #.... ..#.. ..... ..... ..... ..... ..... ..... .....",
               "#.##. .##.. ..##. #..#. ..#.. ##.#. #.##. .###. ####. .#### #.##. .####",
               "##..# ..#.. ...#. #.#.. ..#.. #.#.# ##..# #...# #...# #...# ##..# #....",
               "#...# ..#.. ...#. ##... ..#.. #.#.# #...# #...# #...# #...# #.... .###.",
               "#...# ..#.. ...#. #.#.. ..#.. #.#.# #...# #...# ####. .#### #.... ....#",
               "#...# .###. #..#. #..#. .###. #.#.# #...# .###. #.... ....# #.... ####.",
               "..... ..... .##.. ..... ..... ..... ..... ..... #.... ....# ..... ....."}},
    //    t     u     v     w     x     y     z     {     |     }     ~
    {116, 11, {".#... ..... ..... ..... ..... ..... ..... ...#. ..#.. .#... .....",
               ".#... ..... ..... ..... ..... ..... ..... ..#.. ..#.. ..#.. .....",
               "####. #...# #...# #...# #...# #...# ##### ..#.. ..#.. ..#.. .#...",
               ".#... #...# #...# #...# .#.#. #...# ...#. .#... ..#.. ...#. #.#.#",
               ".#... #...# #...# #.#.# ..#.. #...# ..#.. ..#.. ..#.. ..#.. ...#.",
               ".#..# #..## .#.#. #.#.# .#.#. .#### .#... ..#.. ..#.. ..#.. .....",
               "..##. .##.# ..#.. .#.#. #...# ....# ##### ...#. ..#.. .#... .....",
               "..... ..... ..... ..... ..... .###. ..... ..... ..... ..... ....."}},
};
// clang-format on

// The Latin-1 letters German and French need, composed from an ASCII letter and an accent:
// on a small letter the accent takes rows 0..1 (above the x-height); a capital is drawn five
// rows tall (its rows 2 and 4 dropped: in these letters they repeat a neighbour) below a blank
// row and a one-row accent, so that the accent stands clear of the letter. The cedilla hangs in
// row 7.
enum class Accent : uint8_t { acute, grave, circumflex, diaeresis, cedilla };
struct Composed {
    char32_t code;
    char base;
    Accent accent;
};
constexpr Composed kComposed[] = {
    {0xC0, 'A', Accent::grave},      {0xC2, 'A', Accent::circumflex}, {0xC4, 'A', Accent::diaeresis},
    {0xC7, 'C', Accent::cedilla},    {0xC8, 'E', Accent::grave},      {0xC9, 'E', Accent::acute},
    {0xCA, 'E', Accent::circumflex}, {0xCB, 'E', Accent::diaeresis},  {0xCE, 'I', Accent::circumflex},
    {0xCF, 'I', Accent::diaeresis},  {0xD4, 'O', Accent::circumflex}, {0xD6, 'O', Accent::diaeresis},
    {0xD9, 'U', Accent::grave},      {0xDB, 'U', Accent::circumflex}, {0xDC, 'U', Accent::diaeresis},
    {0xE0, 'a', Accent::grave},      {0xE2, 'a', Accent::circumflex}, {0xE4, 'a', Accent::diaeresis},
    {0xE7, 'c', Accent::cedilla},    {0xE8, 'e', Accent::grave},      {0xE9, 'e', Accent::acute},
    {0xEA, 'e', Accent::circumflex}, {0xEB, 'e', Accent::diaeresis},  {0xEE, 'i', Accent::circumflex},
    {0xEF, 'i', Accent::diaeresis},  {0xF4, 'o', Accent::circumflex}, {0xF6, 'o', Accent::diaeresis},
    {0xF9, 'u', Accent::grave},      {0xFB, 'u', Accent::circumflex}, {0xFC, 'u', Accent::diaeresis},
};
// Each accent's rows above a small letter (rows 0, 1) and above a capital (row 0), as bits.
constexpr uint8_t kAccentSmall[][2] = {{0x10, 0x20}, {0x40, 0x20}, {0x20, 0x50}, {0x00, 0x50}, {0, 0}};
constexpr uint8_t kAccentCapital[] = {0x10, 0x40, 0x20, 0x50, 0};

// Drawn whole: the sharp s, the degree sign, the superscript two and the no-break space.
constexpr ArtBlock kLatinArt[] = {
    //   ß
    {0xDF, 1, {".##..", "#..#.", "#..#.", "#.#..", "#..#.", "#...#", "#.##.", "#...."}},
    //   °
    {0xB0, 1, {".##..", "#..#.", "#..#.", ".##..", ".....", ".....", ".....", "....."}},
    //   ² (a unit squared: u², FE)
    {0xB2, 1, {".##..", "...#.", "..#..", ".###.", ".....", ".....", ".....", "....."}},
    //   no-break space
    {0xA0, 1, {".....", ".....", ".....", ".....", ".....", ".....", ".....", "....."}},
};

using GlyphTable = std::array<uint8_t, kBuiltinGlyphs * kCellHeight>;
using Drawn = std::array<bool, kBuiltinGlyphs>;

// Throwing here is a compile error, since the table is built in a constant expression. Without
// exceptions (the microcontroller firmware, docs/microcontroller.md) GCC refuses a throw even
// there, so a call to a function that is not constexpr stops the constant evaluation the same
// way.
#if defined(__cpp_exceptions)
#define NONEUCLID_TABLE_ERROR(why) throw why
#else
void table_error(const char*) {}
#define NONEUCLID_TABLE_ERROR(why) table_error(why)
#endif
constexpr void draw_block(const ArtBlock& block, GlyphTable& table, Drawn& drawn) {
    for (int r = 0; r < kCellHeight; ++r) {
        const std::string_view row = block.rows[r];
        if (row.size() != std::size_t(block.count * kCellWidth - 1))
            NONEUCLID_TABLE_ERROR("bad row length");
        for (int j = 0; j < block.count; ++j) {
            const int code = int(block.first) + j;
            uint8_t bits = 0;
            for (int c = 0; c < kCellWidth - 1; ++c) {
                const char p = row[std::size_t(j * kCellWidth + c)];
                if (p == '#') {
                    bits = uint8_t(bits | (0x80 >> c));
                } else if (p != '.') {
                    NONEUCLID_TABLE_ERROR("a glyph pixel is neither '#' nor '.'");
                }
            }
            if (j + 1 < block.count && row[std::size_t(j * kCellWidth + kCellWidth - 1)] != ' ')
                NONEUCLID_TABLE_ERROR("glyphs must be separated by one space");
            table[std::size_t(code * kCellHeight + r)] = bits;
        }
    }
    for (int j = 0; j < block.count; ++j) {
        const int code = int(block.first) + j;
        if (code >= kBuiltinGlyphs || drawn[std::size_t(code)])
            NONEUCLID_TABLE_ERROR("glyph drawn twice");
        drawn[std::size_t(code)] = true;
    }
}

constexpr void compose(const Composed& g, GlyphTable& table, Drawn& drawn) {
    const auto row = [&](int code, int r) -> uint8_t& { return table[std::size_t(code * kCellHeight + r)]; };
    const int code = int(g.code), base = int(g.base), a = int(g.accent);
    if (code >= kBuiltinGlyphs || drawn[std::size_t(code)] || !drawn[std::size_t(base)])
        NONEUCLID_TABLE_ERROR("a composed glyph is drawn twice, or its letter is not drawn");
    const bool capital = g.base >= 'A' && g.base <= 'Z';
    for (int r = 0; r < kCellHeight; ++r) row(code, r) = row(base, r);
    if (g.accent != Accent::cedilla) {
        if (capital) {  // the accent, a blank row, and the letter's rows 0, 1, 3, 5, 6 in rows 2..6
            constexpr int kKept[] = {0, 1, 3, 5, 6};
            for (int r = 0; r < 5; ++r) row(code, 2 + r) = row(base, kKept[r]);
            row(code, 1) = 0;
            row(code, 0) = kAccentCapital[a];
        } else {
            row(code, 0) = kAccentSmall[a][0];
            row(code, 1) = kAccentSmall[a][1];
        }
    } else {
        row(code, 7) = 0x20;
    }
    drawn[std::size_t(code)] = true;
}

// The table, and which of its glyphs are drawn (the rest are '?').
struct Built {
    GlyphTable table{};
    Drawn drawn{};
};

constexpr Built build_builtin() {
    Built b;
    for (const ArtBlock& block : kArt) draw_block(block, b.table, b.drawn);
    for (const ArtBlock& block : kLatinArt) draw_block(block, b.table, b.drawn);
    for (const Composed& g : kComposed) compose(g, b.table, b.drawn);
    for (int code = 32; code <= 126; ++code)
        if (!b.drawn[std::size_t(code)])
            NONEUCLID_TABLE_ERROR("a printable ASCII glyph is missing");
    // The rest (control characters, DEL, Latin-1 not drawn here) show '?'.
    for (int code = 0; code < kBuiltinGlyphs; ++code) {
        if (b.drawn[std::size_t(code)])
            continue;
        for (int r = 0; r < kCellHeight; ++r)
            b.table[std::size_t(code * kCellHeight + r)] = b.table[std::size_t('?' * kCellHeight + r)];
    }
    return b;
}

constexpr Built kBuilt = build_builtin();

}  // namespace

const Font& builtin_font() {
    static constexpr Font font{kCellWidth, kCellHeight, kBuiltinGlyphs, 1, kBuilt.table.data()};
    return font;
}

bool builtin_font_draws(char32_t c) { return c < char32_t(kBuiltinGlyphs) && kBuilt.drawn[std::size_t(c)]; }

}  // namespace noneuclid::render
