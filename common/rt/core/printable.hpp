// Text from outside (a path, a key of a scene file, a library's message) made fit for a one-line message:
// control bytes are escaped, so a newline or an escape sequence in a file name can neither split the message
// nor reach the terminal.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace rt {

// `s` with \n, \r, \t, \xNN for every other control byte (and DEL), \u0080..\u009f for a C1 control
// character and \xNN for a byte that is not well-formed UTF-8 (a Latin-1 é is \xe9); cut after `longest`
// bytes (or up to 3 fewer, not to split a character) with "..." when longer.
std::string printable(std::string_view s, std::size_t longest = std::string_view::npos);

// A path as a message shows it: as it is when it holds only letters, digits and . / _ - + , = : @ % ~;
// otherwise (spaces, quotes, control bytes, other bytes, or empty) in double quotes, escaped as printable
// does, with \" for a quote.
std::string shown(const std::filesystem::path& path);

// A value given on the command line as a message shows it: in double quotes, printable, at most 64 bytes.
std::string shown_value(std::string_view text);

}  // namespace rt
