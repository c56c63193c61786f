#include "rt/core/printable.hpp"

#include <cstdio>

namespace rt {

namespace {

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
        char hex[8];
        std::snprintf(hex, sizeof hex, "\\x%02x", byte);
        out += hex;
    } else {
        out += c;
    }
}

bool plain(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string_view("./_-+,=:@%~").find(c) != std::string_view::npos;
}

}  // namespace

std::string printable(std::string_view s, std::size_t longest) {
    std::string out;
    for (const char c : s.substr(0, longest)) append_escaped(out, c, false);
    if (s.size() > longest) out += "...";
    return out;
}

std::string shown(const std::filesystem::path& path) {
    const std::string& s = path.native();
    bool is_plain = !s.empty();
    for (const char c : s) is_plain = is_plain && plain(c);
    if (is_plain) return s;
    std::string out = "\"";
    for (const char c : s) append_escaped(out, c, true);
    return out + "\"";
}

std::string shown_value(std::string_view text) {
    return "\"" + printable(std::string(text), 64) + "\"";
}

}  // namespace rt
