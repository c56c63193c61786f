#include "rt/core/formatted.hpp"

#include <cstdio>

namespace rt {

std::string formatted(const char* pattern, double a, double b, double c) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

}  // namespace rt
