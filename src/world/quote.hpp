// Text from an input file (a scene, a board, an actions file), made safe for a message: what a
// file holds must never reach the terminal raw. An ESC sequence in a body name would restyle the
// terminal, a newline in a key would forge a second line, a NUL would cut the sentence when it
// is printed, and a 1 MiB token would make a 1 MiB message. Every place where file content
// goes into an error sentence passes it through quote() or printable().
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace noneuclid::world {

// How many characters of file content a message shows before "…"; of a file's path (which
// may come from a file too: a board's scene, a recording's); of a sentence from a library.
inline constexpr std::size_t kQuoteLimit = 60;
inline constexpr std::size_t kPathLimit = 256;
inline constexpr std::size_t kSentenceLimit = 200;

// `s` as a message may show it. Valid UTF-8 text stays as it is, except:
//  - a backslash is written \\ (so that the escapes below are unambiguous);
//  - control characters (U+0000-U+001F, U+007F) are written \xNN: \x1b, \x0a, \x00;
//  - every byte that is not part of valid UTF-8 is written \xNN;
//  - the C1 controls (U+0080-U+009F), the line and paragraph separators (U+2028, U+2029), the
//    bidirectional-text controls (U+200E, U+200F, U+202A-U+202E, U+2066-U+2069) and the
//    byte-order mark (U+FEFF), which a terminal may act on or which reorder what is shown, are
//    written \uNNNN.
// At most `limit` characters (code points; an escape counts its own characters): a longer
// result keeps its first `limit` - 1, never cutting an escape or a UTF-8 sequence, then "…".
// With `backslash` false a backslash stays single: for a library's sentence that has its own
// escapes ("saw '\r'").
std::string printable(std::string_view s, std::size_t limit = kQuoteLimit, bool backslash = true);

// printable(s, limit) between single quotes: 'ship', 'a\x1b[31m', 'aaaa…'.
std::string quote(std::string_view s, std::size_t limit = kQuoteLimit);

// Whether `s` is valid UTF-8 with nothing printable() would escape but backslashes: a name or
// a path that can be shown, and written back into a line of text, as it is.
bool is_plain(std::string_view s);

// Strict UTF-8 decoding of the sequence that starts at s[i]: the shortest form only, no UTF-16
// surrogates, nothing above U+10FFFF. On success sets `cp` and `length` (1-4) and returns true;
// on an invalid or cut sequence returns false (s[i] is then a byte to show as \xNN).
bool utf8_decode(std::string_view s, std::size_t i, char32_t& cp, std::size_t& length);

// Names as a sentence's list of choices: "a, b or c" (`quoted`: "\"a\", \"b\" or \"c\"", as a
// TOML file writes them). The registries' names (engines, projections, scenes, ...) reach help
// and error sentences through this.
std::string or_list(const std::vector<std::string>& names, bool quoted = false);

}  // namespace noneuclid::world
