// A line of a report or a note, printf-style: up to three numbers, as doubles, into a pattern.
#pragma once

#include <string>

namespace rt {

// The pattern with a, b and c put in (the pattern's conversions must all be floating-point: %g, %.1f, ...).
std::string formatted(const char* pattern, double a, double b = 0, double c = 0);

}  // namespace rt
