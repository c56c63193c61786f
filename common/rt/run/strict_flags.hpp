// Every flag value of every chapter read strictly, as the scene file's numbers are: CLI11 on its own reads
// " -1" as 2^64 − 1 for an unsigned flag, 18446744073709551616 as 2^64 − 1, 0x10 as 16, 010 as 8, and "nan"
// as a number inside any range (every comparison with NaN is false), and takes "" for a file name.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace rt {

// A whole number that is a power of two (1, 2, 4, ...), checked after the strict reading.
CLI::Validator power_of_two();

// Adds to every option of `app` the check of its kind, run before its other checks:
//  - whole numbers (INT, UINT): decimal digits only, no leading 0, a leading '-' for signed ones, wholly
//    consumed, within 64 bits (the option's own range check then applies);
//  - real numbers (FLOAT): a decimal number wholly consumed, finite, of magnitude at most 1e30;
//  - text (TEXT, a file name or a choice): not empty.
// Call it once every option has been added, before parsing.
void make_values_strict(CLI::App& app);

// Reads the command line into `app`'s options, once every option has been added, made strict first. Returns
// the exit status when the command line asked for help instead of a run; throws an InputError,
// "usage: <what is wrong> (see --help)", for a bad flag.
std::optional<int> parse_strictly(CLI::App& app, int argc, char** argv);

// The same for a program that is not a chapter (a benchmark, rt_scene): a bad flag is printed as one line,
// "<program>: usage: ...", as a chapter prints it, and returns kExitBadInput.
std::optional<int> read_flags(CLI::App& app, int argc, char** argv);

}  // namespace rt
