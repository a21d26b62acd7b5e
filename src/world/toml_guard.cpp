// The check a scene or board file passes before toml++ sees it (toml_reader.hpp says why).
#include <cstdio>

#include "world/quote.hpp"
#include "world/toml_reader.hpp"

namespace noneuclid::world::tomlr {

namespace {

std::string code_point(char32_t c) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
    return buf;
}

}  // namespace

bool toml_guard(std::string_view text, long& line, long& column, std::string& message) {
    enum State { outside, comment, basic, literal, ml_basic, ml_literal };
    State state = outside;
    bool after_escape = false;       // the previous character was a backslash in a basic string
    bool line_continuation = false;  // skipping the whitespace after a backslash in a basic string
    line = 1, column = 1;
    std::size_t i = 0;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // a UTF-8 byte-order mark: toml++ skips it
    auto fail = [&](std::string m) {
        message = "not valid TOML: " + std::move(m);
        return false;
    };
    // The run of `q` starting at i (a closing delimiter and up to two quotes of content).
    auto run_of = [&](char q) {
        std::size_t n = 0;
        while (i + n < text.size() && text[i + n] == q) ++n;
        return n;
    };
    while (i < text.size()) {
        char32_t c = 0;
        std::size_t len = 0;
        if (!utf8_decode(text, i, c, len))
            return fail("the byte " + printable(text.substr(i, 1)) + " is not UTF-8 (save the file as UTF-8)");
        if (c == '\r') {
            if (i + 1 < text.size() && text[i + 1] == '\n') {
                ++i;  // CR LF: a line end like LF, handled below
                continue;
            }
            return fail("a carriage return (\\x0d) not followed by a line feed: lines end with LF or CR LF");
        }
        if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7F)
            return fail("the control character " + printable(text.substr(i, 1)) +
                        " (TOML allows only tab and line ends; write it as an escape in a string)");
        if (line_continuation) {
            if (c == ' ' || c == '\t' || c == '\n') {
                if (c == '\n') ++line, column = 0;
                ++i, ++column;
                continue;
            }
            line_continuation = false;
            if (c >= 0x80)
                return fail("the character " + quote(text.substr(i, len)) + " (" + code_point(c) +
                            ") right after a line-ending backslash: write it as an escape, \\u" +
                            code_point(c).substr(2));
        }
        if (c == '\n') {
            if (state == comment || state == basic || state == literal) state = outside;
            after_escape = false;
            ++line, column = 1, ++i;
            continue;
        }
        std::size_t advance = len;
        switch (state) {
            case outside:
                if (c == '#') {
                    state = comment;
                } else if (c == '"' || c == '\'') {
                    const bool multi = run_of(static_cast<char>(c)) >= 3;
                    state = c == '"' ? (multi ? ml_basic : basic) : (multi ? ml_literal : literal);
                    advance = multi ? 3 : 1;
                } else if (c >= 0x80) {
                    return fail("the character " + quote(text.substr(i, len)) + " (" + code_point(c) +
                                ") outside quotes: a key or a value with it must be in quotes");
                }
                break;
            case comment: break;
            case basic:
            case ml_basic:
                if (after_escape) {
                    after_escape = false;
                    // A backslash before whitespace is a line-ending backslash (or, in a one-line
                    // string, a bad escape): toml++ skips the whitespace and line ends after it.
                    if (c == ' ' || c == '\t') {
                        line_continuation = true;
                        continue;  // the same character again, in the skip
                    }
                } else if (c == '\\') {
                    after_escape = true;
                    if (i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r'))
                        line_continuation = true, after_escape = false;
                } else if (c == '"') {
                    const std::size_t n = run_of('"');
                    if (state == basic) state = outside, advance = 1;
                    else if (n >= 3) state = outside, advance = n;
                    else advance = n;
                }
                break;
            case literal:
            case ml_literal:
                if (c == '\'') {
                    const std::size_t n = run_of('\'');
                    if (state == literal) state = outside, advance = 1;
                    else if (n >= 3) state = outside, advance = n;
                    else advance = n;
                }
                break;
        }
        // Columns count characters; a run of quotes is that many.
        column += static_cast<long>(c < 0x80 ? advance : 1);
        i += advance;
    }
    return true;
}

}  // namespace noneuclid::world::tomlr
