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

bool bare_key_character(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// A table header starts at text[i] ('['). toml++ (3.3.0, 3.4.0) reads its name with an
// assertion, not a check, that it begins with a key's character: `[*]`, `[[#x]]`, `[\n`
// fail the assertion (and are undefined behaviour without assertions). Checks that character.
bool table_header(std::string_view text, std::size_t i, std::string& message) {
    std::size_t k = i + 1;
    const bool array = k < text.size() && text[k] == '[';
    if (array) ++k;
    while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) ++k;
    if (k < text.size()) {
        const char c = text[k];
        if (c == '\r' && (k + 1 == text.size() || text[k + 1] != '\n')) return true;  // a lone CR: refused as one
        if (bare_key_character(c) || c == '"' || c == '\'' || c == ']' || (c == '[' && !array)) return true;
    }
    std::string found = "the end of the file";
    if (k < text.size()) {
        char32_t c = 0;
        std::size_t len = 1;
        if (!utf8_decode(text, k, c, len)) len = 1;
        found = text[k] == '\n' || text[k] == '\r' ? "the end of the line" : quote(text.substr(k, len));
    }
    message = std::string("expected a table's name after '") + (array ? "[[" : "[") + "', found " + found;
    return false;
}

bool digit(char c) { return c >= '0' && c <= '9'; }

// A value that starts at text[i] (a digit) with a date: toml++ reads a time after a 'T' or 't'
// with an assertion, not a check, that a digit follows (`1979-05-27tz:`); and when the first
// ten characters of a value (underscores aside) have '-' at the fifth and the eighth, it takes
// a space and a digit after them for a time's start and scans on past the value's end if a
// second digit does not follow (`1979-05-27 1]`, `1979-02-PH 9`). A time's hour has two digits:
// anything else after a date's separator is refused here.
bool date_time(std::string_view text, std::size_t i, std::string& message) {
    const std::string_view d = text.substr(i, 12);
    std::string found;
    if (d.size() >= 11 && digit(d[0]) && digit(d[1]) && digit(d[2]) && digit(d[3]) && d[4] == '-' && digit(d[5]) &&
        digit(d[6]) && d[7] == '-' && digit(d[8]) && digit(d[9]) && (d[10] == 'T' || d[10] == 't') &&
        (d.size() < 12 || !digit(d[11])))
        found = std::string(d.substr(0, 11));
    // The value's characters as toml++ collects them (underscores left out), to its end.
    std::string chars;
    std::size_t k = i;
    for (; k < text.size() && chars.size() <= 10; ++k) {
        const char c = text[k];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ']' || c == '}' || c == ',' || c == '#') break;
        if (c != '_') chars += c;
    }
    if (chars.size() == 10 && chars[4] == '-' && chars[7] == '-' && k + 1 < text.size() && text[k] == ' ' &&
        digit(text[k + 1]) && (k + 2 == text.size() || !digit(text[k + 2])))
        found = std::string(text.substr(i, k + 2 - i));
    if (found.empty()) return true;
    message = "expected a date and a time (YYYY-MM-DDTHH:MM:SS), found " + quote(found);
    return false;
}

}  // namespace

bool toml_guard(std::string_view text, long& line, long& column, std::string& message) {
    enum State { outside, comment, basic, literal, ml_basic, ml_literal };
    State state = outside;
    std::string open;            // the arrays ('[') and inline tables ('{') open in a value
    bool value_on_line = false;  // a '=' outside them on this line: a '[' opens an array
    char before = '\n';          // the last character outside strings but spaces and tabs
    bool in_token = false;       // in a bare value: a number, a date, a boolean or a bad token
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
            if (open.empty()) value_on_line = false;
            if (state == outside) before = '\n';
            in_token = false;
            after_escape = false;
            ++line, column = 1, ++i;
            continue;
        }
        std::size_t advance = len;
        switch (state) {
            case outside: {
                // A bare value (a number, a date, true, a bad token) runs to a value's end, and
                // toml++ reads it all before it judges it: a quote or a bracket inside it is not
                // a string's or an array's start (`x = +z"é"`, `[[-Y["é`).
                const bool value_start = before == '=' || (!open.empty() && open.back() == '[' &&
                                                           (before == '[' || before == ',' || before == '\n'));
                if (in_token && (c == ' ' || c == '\t' || c == ']' || c == '}' || c == ',' || c == '#')) {
                    in_token = false;
                } else if (!in_token && value_start &&
                           (c >= 0x80 || std::string_view(" \t[{\"'#]},").find(static_cast<char>(c)) == std::string_view::npos)) {
                    in_token = true;
                    if (digit(static_cast<char>(c)) && !date_time(text, i, message)) return fail(message);
                }
                if (in_token) {
                    if (c >= 0x80)
                        return fail("the character " + quote(text.substr(i, len)) + " (" + code_point(c) +
                                    ") outside quotes: a key or a value with it must be in quotes");
                } else if (c == '[' && open.empty() && !value_on_line) {
                    if (!table_header(text, i, message)) return fail(message);
                } else if (c == '[' || c == '{') {
                    open.push_back(static_cast<char>(c));
                } else if ((c == ']' || c == '}') && !open.empty()) {
                    // toml++ takes a '}' where an array expects a value as one (an assertion):
                    // a closing bracket must match the innermost opening one.
                    if ((c == ']') != (open.back() == '['))
                        return fail(std::string("'") + static_cast<char>(c) + "' closes " +
                                    (open.back() == '[' ? "an array, which ']' closes" : "an inline table, which '}' closes"));
                    open.pop_back();
                } else if (c == '=' && open.empty()) {
                    value_on_line = true;
                } else if (c == '#') {
                    state = comment;
                } else if ((c == '"' || c == '\'') && std::string_view("=[{,.\n").find(before) != std::string_view::npos) {
                    // A string: where a key or a value begins. A quote anywhere else (`x = +z"é"`)
                    // is part of a bad token that toml++ reads on, character by character.
                    const bool multi = run_of(static_cast<char>(c)) >= 3;
                    state = c == '"' ? (multi ? ml_basic : basic) : (multi ? ml_literal : literal);
                    advance = multi ? 3 : 1;
                } else if (c >= 0x80) {
                    return fail("the character " + quote(text.substr(i, len)) + " (" + code_point(c) +
                                ") outside quotes: a key or a value with it must be in quotes");
                }
                if (c != ' ' && c != '\t') before = static_cast<char>(c);
                break;
            }
            case comment: break;
            case basic:
            case ml_basic:
                if (after_escape) {
                    after_escape = false;
                    // toml++ asks its whitespace table about the character after a backslash,
                    // and the table has holes for non-ASCII ones. No escape is one anyway.
                    if (c >= 0x80)
                        return fail("the character " + quote(text.substr(i, len)) + " (" + code_point(c) +
                                    ") after a backslash: an escape is \\n, \\t, \\\", \\\\, \\uXXXX and the like");
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
                    if (state == outside) before = '"';
                }
                break;
            case literal:
            case ml_literal:
                if (c == '\'') {
                    const std::size_t n = run_of('\'');
                    if (state == literal) state = outside, advance = 1;
                    else if (n >= 3) state = outside, advance = n;
                    else advance = n;
                    if (state == outside) before = '"';
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
