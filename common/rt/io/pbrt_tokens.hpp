// The words of a pbrt-v4 scene file: directives and bare words (WorldBegin, true), quoted strings, numbers
// and the brackets of a list, each with its line and column, so that every error names its place
// ("scene.pbrt:12:5: ..."). `#` starts a comment to the end of the line. The reader (pbrt_reader.hpp)
// gives them meaning.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rt {

enum class PbrtTokenKind { kWord, kString, kNumber, kOpen, kClose };

struct PbrtToken {
    PbrtTokenKind kind = PbrtTokenKind::kWord;
    std::string text;    // a string's contents without its quotes (escapes resolved); the word or number as written
    double number = 0;   // kNumber: its value, finite
    int line = 1;
    int column = 1;      // in bytes, from 1
};

// Splits `text` into tokens. `place` names the file in messages ("scene.pbrt" or "main.pbrt: part.pbrt"):
// an unterminated string, a newline inside one, an unknown escape, text that is not printable UTF-8 in a
// string, or a number that is not finite (1e400) throws InputError "PLACE:LINE:COLUMN: ...".
std::vector<PbrtToken> tokenize_pbrt(std::string_view text, const std::string& place);

// "PLACE:LINE:COLUMN: " for a token of the file named `place`.
std::string pbrt_location(const std::string& place, const PbrtToken& token);

}  // namespace rt
