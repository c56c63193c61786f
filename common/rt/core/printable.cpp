#include "rt/core/printable.hpp"

#include <algorithm>
#include <cstdio>

namespace rt {

namespace {

void append_hex(std::string& out, unsigned char byte) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", byte);
    out += hex;
}

void append_escaped(std::string& out, char c, bool quote_too) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
        out += "\\n";
    } else if (c == '\r') {
        out += "\\r";
    } else if (c == '\t') {
        out += "\\t";
    } else if (c == '\\' && quote_too) {
        out += "\\\\";
    } else if (c == '"' && quote_too) {
        out += "\\\"";
    } else if (byte < 0x20 || byte == 0x7f) {
        append_hex(out, byte);
    } else {
        out += c;
    }
}

// The length of the well-formed UTF-8 sequence of two to four bytes at the start of `s` (no overlong form,
// no surrogate, at most U+10FFFF), or 0.
std::size_t utf8_length(std::string_view s) {
    const auto byte = [&](std::size_t i) -> unsigned {
        return i < s.size() ? static_cast<unsigned char>(s[i]) : 0;
    };
    const unsigned lead = byte(0);
    std::size_t length = 0;
    if (lead >= 0xc2 && lead <= 0xdf) length = 2;
    if (lead >= 0xe0 && lead <= 0xef) length = 3;
    if (lead >= 0xf0 && lead <= 0xf4) length = 4;
    // The second byte's range narrows after E0, ED, F0 and F4; every other continuation byte is 80..BF.
    const unsigned low = lead == 0xe0 ? 0xa0 : lead == 0xf0 ? 0x90 : 0x80;
    const unsigned high = lead == 0xed ? 0x9f : lead == 0xf4 ? 0x8f : 0xbf;
    if (length == 0 || byte(1) < low || byte(1) > high) return 0;
    for (std::size_t i = 2; i < length; ++i) {
        if (byte(i) < 0x80 || byte(i) > 0xbf) return 0;
    }
    return length;
}

// `s` escaped: control bytes as append_escaped does, a C1 control (U+0080..U+009F) as \u0080..\u009f, a byte
// that is not part of well-formed UTF-8 as \xNN; every other character as it is.
void append_escaped(std::string& out, std::string_view s, bool quote_too) {
    for (std::size_t i = 0; i < s.size();) {
        const auto byte = static_cast<unsigned char>(s[i]);
        const std::size_t length = byte < 0x80 ? 1 : utf8_length(s.substr(i));
        if (length == 1) {
            append_escaped(out, s[i], quote_too);
        } else if (length == 0) {
            append_hex(out, byte);
        } else if (byte == 0xc2 && static_cast<unsigned char>(s[i + 1]) <= 0x9f) {
            char code[8];
            std::snprintf(code, sizeof code, "\\u%04x", static_cast<unsigned char>(s[i + 1]));
            out += code;
        } else {
            out.append(s.substr(i, length));
        }
        i += std::max<std::size_t>(length, 1);
    }
}

bool plain(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string_view("./_-+,=:@%~").find(c) != std::string_view::npos;
}

}  // namespace

std::string printable(std::string_view s, std::size_t longest) {
    // The cut moves back (at most 3 bytes) to the start of a character, so as not to split one.
    std::size_t cut = std::min(longest, s.size());
    for (int k = 0; k < 3 && cut > 0 && cut < s.size() && (static_cast<unsigned char>(s[cut]) & 0xc0) == 0x80;
         ++k) {
        --cut;
    }
    std::string out;
    append_escaped(out, s.substr(0, cut), false);
    if (cut < s.size()) out += "...";
    return out;
}

std::string shown(const std::filesystem::path& path) {
    const std::string& s = path.native();
    bool is_plain = !s.empty();
    for (const char c : s) is_plain = is_plain && plain(c);
    if (is_plain) return s;
    std::string out = "\"";
    append_escaped(out, s, true);
    return out + "\"";
}

std::string shown_value(std::string_view text) {
    return "\"" + printable(std::string(text), 64) + "\"";
}

}  // namespace rt
