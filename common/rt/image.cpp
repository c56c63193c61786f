#include "rt/image.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "rt/errors.hpp"
#include "rt/pixel_sums.hpp"

namespace rt {

namespace {
std::string gigabytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
    return text;
}
}  // namespace

void check_image_size(long long width, long long height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) throw InputError("image size must be positive, got " + size);
    if (width > kMaxImageSide || height > kMaxImageSide) {
        throw InputError("image size " + size + " is too large: at most " + std::to_string(kMaxImageSide) +
                         " pixels a side");
    }
    const double needed = double(width) * double(height) * double(sizeof(Color) + sizeof(PixelSum));
    // Half of this machine's memory, and half of what this process may use (ulimit -v): the tighter is named.
    const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
    rlimit limit{};
    const bool limited = getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
    const double process = limited ? double(limit.rlim_cur) : 0;
    const std::string needs =
        "image size " + size + " needs " + gigabytes(needed) + " of buffers, more than half of ";
    if (limited && (!(memory > 0) || process < memory) && needed > process / 2) {
        throw InputError(needs + "the " + gigabytes(process) + " this process may use (ulimit -v)");
    }
    if (memory > 0 && needed > memory / 2) {
        throw InputError(needs + "this machine's " + gigabytes(memory) + " of memory");
    }
    if (limited && needed > process / 2) {
        throw InputError(needs + "the " + gigabytes(process) + " this process may use (ulimit -v)");
    }
}

Image::Image(int width, int height) : width_(width), height_(height) {
    check_image_size(width, height);
    pixels_.assign(std::size_t(width) * std::size_t(height), Color(0));
}

double Image::mean() const {
    double sum = 0;
    for (const Color& c : pixels_) sum += double(c.r) + double(c.g) + double(c.b);
    return pixels_.empty() ? 0.0 : sum / (3.0 * double(pixels_.size()));
}

bool Image::all_finite() const {
    for (const Color& c : pixels_) {
        if (!is_finite(c)) return false;
    }
    return true;
}

}  // namespace rt
