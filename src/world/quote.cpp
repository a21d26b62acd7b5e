#include "world/quote.hpp"

#include <cstdint>
#include <cstdio>

namespace noneuclid::world {

bool utf8_decode(std::string_view s, std::size_t i, char32_t& cp, std::size_t& length) {
    const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(s[k]); };
    const std::uint8_t b0 = byte(i);
    if (b0 < 0x80) {
        cp = b0, length = 1;
        return true;
    }
    std::size_t n;
    char32_t c, min;
    if (b0 >= 0xC2 && b0 <= 0xDF) n = 2, c = b0 & 0x1Fu, min = 0x80;
    else if (b0 >= 0xE0 && b0 <= 0xEF) n = 3, c = b0 & 0x0Fu, min = 0x800;
    else if (b0 >= 0xF0 && b0 <= 0xF4) n = 4, c = b0 & 0x07u, min = 0x10000;
    else return false;  // a continuation byte, an overlong lead (C0, C1) or F5-FF
    if (s.size() - i < n) return false;
    for (std::size_t k = 1; k < n; ++k) {
        const std::uint8_t b = byte(i + k);
        if ((b & 0xC0) != 0x80) return false;
        c = (c << 6) | (b & 0x3Fu);
    }
    if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return false;
    cp = c, length = n;
    return true;
}

namespace {

// A code point that is valid UTF-8 but that a terminal may act on, or that reorders text.
bool shown_escaped(char32_t c) {
    return (c >= 0x80 && c <= 0x9F) || c == 0x2028 || c == 0x2029 || c == 0x200E || c == 0x200F ||
           (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069) || c == 0xFEFF;
}

}  // namespace

bool is_plain(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        char32_t cp = 0;
        std::size_t len = 0;
        if (!utf8_decode(s, i, cp, len) || cp < 0x20 || cp == 0x7F || shown_escaped(cp)) return false;
        i += len;
    }
    return true;
}

std::string printable(std::string_view s, std::size_t limit, bool backslash) {
    std::string out;
    std::size_t chars = 0;  // characters in `out`
    std::size_t cut = std::string::npos;  // where the result is cut if it proves too long
    for (std::size_t i = 0; i < s.size();) {
        char32_t cp = 0;
        std::size_t len = 0;
        char unit[16];
        std::string_view piece;  // what this input unit becomes
        std::size_t piece_chars = 0;
        if (!utf8_decode(s, i, cp, len)) {
            std::snprintf(unit, sizeof unit, "\\x%02x", static_cast<unsigned>(static_cast<std::uint8_t>(s[i])));
            piece = std::string_view(unit, 4), piece_chars = 4, len = 1;
        } else if (cp < 0x20 || cp == 0x7F) {
            std::snprintf(unit, sizeof unit, "\\x%02x", static_cast<unsigned>(cp));
            piece = std::string_view(unit, 4), piece_chars = 4;
        } else if (shown_escaped(cp)) {
            std::snprintf(unit, sizeof unit, "\\u%04x", static_cast<unsigned>(cp));
            piece = std::string_view(unit, 6), piece_chars = 6;
        } else if (cp == '\\' && backslash) {
            piece = "\\\\", piece_chars = 2;
        } else {
            piece = s.substr(i, len), piece_chars = 1;
        }
        if (cut == std::string::npos && chars + piece_chars > (limit > 0 ? limit - 1 : 0))
            cut = out.size();  // the last point at which "…" still fits
        if (chars + piece_chars > limit) {
            out.resize(cut);
            return out.append("\u2026");
        }
        out.append(piece);
        chars += piece_chars;
        i += len;
    }
    return out;
}

std::string quote(std::string_view s, std::size_t limit) {
    std::string q;  // (built with append: GCC 12 warns falsely on "'" + std::string(s))
    q.append(1, '\'').append(printable(s, limit)).append(1, '\'');
    return q;
}

std::string or_list(const std::vector<std::string>& names, bool quoted) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i) {
        s += i == 0 ? "" : i + 1 == names.size() ? " or " : ", ";
        s += quoted ? "\"" + names[i] + "\"" : names[i];
    }
    return s;
}

}  // namespace noneuclid::world
