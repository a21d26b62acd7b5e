// The check a scene or board file passes before toml++ sees it (toml_reader.hpp says why).
#include <cstdio>

#include "world/quote.hpp"
#include "files/toml_reader.hpp"

namespace noneuclid::files::tomlr {

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
    if (array)
        ++k;
    while (k < text.size() && (text[k] == ' ' || text[k] == '\t'))
        ++k;
    if (k < text.size()) {
        const char c = text[k];
        if (c == '\r' && (k + 1 == text.size() || text[k + 1] != '\n'))
            return true;  // a lone CR: refused as one
        if (bare_key_character(c) || c == '"' || c == '\'' || c == ']' || (c == '[' && !array))
            return true;
    }
    std::string found = "the end of the file";
    if (k < text.size()) {
        char32_t c = 0;
        std::size_t len = 1;
        if (!world::utf8_decode(text, k, c, len))
            len = 1;
        found = text[k] == '\n' || text[k] == '\r' ? "the end of the line" : world::quote(text.substr(k, len));
    }
    message = std::string("expected a table's name after '") + (array ? "[[" : "[") + "', found " + found;
    return false;
}

bool digit(char c) {
    return c >= '0' && c <= '9';
}

// A value that starts at text[i] (a digit) with a date: toml++ reads a time after a 'T' or 't'
// with an assertion, not a check, that a digit follows (`1979-05-27tz:`); and when the first
// ten characters of a value (underscores aside) have '-' at the fifth and the eighth, it takes
// a space and a digit after them for a time's start and scans on past the value's end if a
// second digit does not follow (`1979-05-27 1]`, `1979-02-PH 9`). A time's hour has two digits:
// anything else after a date's separator is refused here.
bool date_time(std::string_view text, std::size_t i, std::string& message) {
    const std::string_view d = text.substr(i, 12);
    std::string found;
    if (d.size() >= 11 && digit(d[0]) && digit(d[1]) && digit(d[2]) && digit(d[3]) && d[4] == '-' && digit(d[5])
        && digit(d[6]) && d[7] == '-' && digit(d[8]) && digit(d[9]) && (d[10] == 'T' || d[10] == 't')
        && (d.size() < 12 || !digit(d[11])))
        found = std::string(d.substr(0, 11));
    // The value's characters as toml++ collects them (underscores left out), to its end.
    std::string chars;
    std::size_t k = i;
    for (; k < text.size() && chars.size() <= 10; ++k) {
        const char c = text[k];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ']' || c == '}' || c == ',' || c == '#')
            break;
        if (c != '_')
            chars += c;
    }
    if (chars.size() == 10 && chars[4] == '-' && chars[7] == '-' && k + 1 < text.size() && text[k] == ' '
        && digit(text[k + 1]) && (k + 2 == text.size() || !digit(text[k + 2])))
        found = std::string(text.substr(i, k + 2 - i));
    if (found.empty())
        return true;
    message = "expected a date and a time (YYYY-MM-DDTHH:MM:SS), found " + world::quote(found);
    return false;
}

}  // namespace

namespace {

// The scan: one pass over the text, in one of six states, tracking what toml++'s reader would
// be in at each character. Each state's rules are a method.
class Guard {
public:
    Guard(std::string_view text, long& line, long& column, std::string& message)
        : text_(text), line_(line), column_(column), message_(message) {}

    bool run() {
        line_ = 1, column_ = 1;
        if (text_.substr(0, 3) == "\xEF\xBB\xBF")
            i_ = 3;  // a UTF-8 byte-order mark: toml++ skips it
        while (i_ < text_.size()) {
            char32_t c = 0;
            std::size_t len = 0;
            if (!world::utf8_decode(text_, i_, c, len))
                return fail("the byte " + world::printable(text_.substr(i_, 1)) + " is not UTF-8 (save the file as UTF-8)");
            if (c == '\r') {
                if (i_ + 1 < text_.size() && text_[i_ + 1] == '\n') {
                    ++i_;  // CR LF: a line end like LF, handled below
                    continue;
                }
                return fail("a carriage return (\\x0d) not followed by a line feed: lines end with LF or CR LF");
            }
            if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7F)
                return fail("the control character " + world::printable(text_.substr(i_, 1))
                            + " (TOML allows only tab and line ends; write it as an escape in a string)");
            if (line_continuation_) {
                if (c == ' ' || c == '\t' || c == '\n') {
                    if (c == '\n')
                        ++line_, column_ = 0;
                    ++i_, ++column_;
                    continue;
                }
                line_continuation_ = false;
                if (c >= 0x80)
                    return fail("the character " + character(c, len)
                                + " right after a line-ending backslash: write it as an escape, \\u"
                                + code_point(c).substr(2));
            }
            if (c == '\n') {
                line_end();
                continue;
            }
            std::size_t advance = len;
            switch (state_) {
                case outside:
                    if (!outside_char(c, len, advance))
                        return false;
                    break;
                case comment:
                    break;
                case basic:
                case ml_basic:
                    if (!basic_char(c, len, advance))
                        return false;
                    if (line_continuation_ && advance == 0)
                        continue;  // the same character again, in the skip
                    break;
                case literal:
                case ml_literal:
                    literal_char(c, advance);
                    break;
            }
            // Columns count characters; a run of quotes is that many.
            column_ += static_cast<long>(c < 0x80 ? advance : 1);
            i_ += advance;
        }
        return true;
    }

private:
    enum State { outside, comment, basic, literal, ml_basic, ml_literal };

    bool fail(std::string m) {
        message_ = "not valid TOML: " + std::move(m);
        return false;
    }
    std::string character(char32_t c, std::size_t len) const {
        return world::quote(text_.substr(i_, len)) + " (" + code_point(c) + ")";
    }
    // The run of `q` starting at i (a closing delimiter and up to two quotes of content).
    std::size_t run_of(char q) const {
        std::size_t n = 0;
        while (i_ + n < text_.size() && text_[i_ + n] == q)
            ++n;
        return n;
    }
    void line_end() {
        if (state_ == comment || state_ == basic || state_ == literal)
            state_ = outside;
        if (open_.empty())
            value_on_line_ = false;
        if (state_ == outside)
            before_ = '\n';
        in_token_ = false;
        after_escape_ = false;
        ++line_, column_ = 1, ++i_;
    }

    // Outside strings and comments: keys, table headers, brackets, bare values.
    bool outside_char(char32_t c, std::size_t len, std::size_t& advance) {
        // A bare value (a number, a date, true, a bad token) runs to a value's end, and toml++
        // reads it all before it judges it: a quote or a bracket inside it is not a string's or
        // an array's start (`x = +z"é"`, `[[-Y["é`).
        const bool value_start =
            before_ == '='
            || (!open_.empty() && open_.back() == '[' && (before_ == '[' || before_ == ',' || before_ == '\n'));
        if (in_token_ && (c == ' ' || c == '\t' || c == ']' || c == '}' || c == ',' || c == '#')) {
            in_token_ = false;
        } else if (!in_token_ && value_start
                   && (c >= 0x80
                       || std::string_view(" \t[{\"'#]},").find(static_cast<char>(c)) == std::string_view::npos)) {
            in_token_ = true;
            if (digit(static_cast<char>(c)) && !date_time(text_, i_, message_))
                return fail(message_);
        }
        if (in_token_) {
            if (c >= 0x80)
                return fail("the character " + character(c, len)
                            + " outside quotes: a key or a value with it must be in quotes");
        } else if (c == '[' && open_.empty() && !value_on_line_) {
            if (!table_header(text_, i_, message_))
                return fail(message_);
        } else if (c == '[' || c == '{') {
            open_.push_back(static_cast<char>(c));
        } else if ((c == ']' || c == '}') && !open_.empty()) {
            // toml++ takes a '}' where an array expects a value as one (an assertion): a closing
            // bracket must match the innermost opening one.
            if ((c == ']') != (open_.back() == '['))
                return fail(
                    std::string("'") + static_cast<char>(c) + "' closes "
                    + (open_.back() == '[' ? "an array, which ']' closes" : "an inline table, which '}' closes"));
            open_.pop_back();
        } else if (c == '=' && open_.empty()) {
            value_on_line_ = true;
        } else if (c == '#') {
            state_ = comment;
        } else if ((c == '"' || c == '\'') && std::string_view("=[{,.\n").find(before_) != std::string_view::npos) {
            // A string: where a key or a value begins. A quote anywhere else (`x = +z"é"`) is
            // part of a bad token that toml++ reads on, character by character.
            const bool multi = run_of(static_cast<char>(c)) >= 3;
            state_ = c == '"' ? (multi ? ml_basic : basic) : (multi ? ml_literal : literal);
            advance = multi ? 3 : 1;
        } else if (c >= 0x80) {
            return fail("the character " + character(c, len)
                        + " outside quotes: a key or a value with it must be in quotes");
        }
        if (c != ' ' && c != '\t')
            before_ = static_cast<char>(c);
        return true;
    }

    // In a basic string, one-line or multi-line: escapes and the closing quotes. Sets advance
    // to 0 when the character is to be read again as part of a line-ending backslash's skip.
    bool basic_char(char32_t c, std::size_t len, std::size_t& advance) {
        if (after_escape_) {
            after_escape_ = false;
            // toml++ asks its whitespace table about the character after a backslash, and the
            // table has holes for non-ASCII ones. No escape is one anyway.
            if (c >= 0x80)
                return fail("the character " + character(c, len)
                            + " after a backslash: an escape is \\n, \\t, \\\", \\\\, \\uXXXX and the like");
            // A backslash before whitespace is a line-ending backslash (or, in a one-line string,
            // a bad escape): toml++ skips the whitespace and line ends after it.
            if (c == ' ' || c == '\t') {
                line_continuation_ = true;
                advance = 0;
            }
        } else if (c == '\\') {
            after_escape_ = true;
            if (i_ + 1 < text_.size() && (text_[i_ + 1] == '\n' || text_[i_ + 1] == '\r'))
                line_continuation_ = true, after_escape_ = false;
        } else if (c == '"') {
            closing_quotes('"', advance);
        }
        return true;
    }

    // In a literal string, one-line or multi-line: only the closing quotes matter.
    void literal_char(char32_t c, std::size_t& advance) {
        if (c == '\'')
            closing_quotes('\'', advance);
    }

    // A run of the string's quote `q`: a one-line string ends at the first; a multi-line one
    // at a run of three or more (the quotes before the last three are its content), and a run
    // of one or two is content.
    void closing_quotes(char q, std::size_t& advance) {
        const std::size_t n = run_of(q);
        if (state_ == basic || state_ == literal)
            state_ = outside, advance = 1;
        else if (n >= 3)
            state_ = outside, advance = n;
        else
            advance = n;
        if (state_ == outside)
            before_ = '"';
    }

    std::string_view text_;
    long& line_;
    long& column_;
    std::string& message_;
    std::size_t i_ = 0;
    State state_ = outside;
    std::string open_;                // the arrays ('[') and inline tables ('{') open in a value
    bool value_on_line_ = false;      // a '=' outside them on this line: a '[' opens an array
    char before_ = '\n';              // the last character outside strings but spaces and tabs
    bool in_token_ = false;           // in a bare value: a number, a date, a boolean or a bad token
    bool after_escape_ = false;       // the previous character was a backslash in a basic string
    bool line_continuation_ = false;  // skipping the whitespace after a backslash in a basic string
};

}  // namespace

bool toml_guard(std::string_view text, long& line, long& column, std::string& message) {
    return Guard(text, line, column, message).run();
}

}  // namespace noneuclid::files::tomlr
