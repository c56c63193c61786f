#include "rt/render/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace rt {

Progress::Progress(ProgressStyle style) : style_(style) {
    if (style_ == ProgressStyle::kAuto)
        style_ = isatty(STDERR_FILENO) ? ProgressStyle::kBar : ProgressStyle::kLines;
}

void Progress::show(double fraction, double elapsed) {
    const double remaining = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
    if (style_ == ProgressStyle::kBar) {
        constexpr int kWidth = 30;
        const int filled = std::clamp(int(fraction * kWidth), 0, kWidth);
        std::fprintf(stderr, "\r[%.*s%*s] %3d%%  elapsed %.1fs  remaining %.1fs ", filled,
                     "##############################", kWidth - filled, "", int(fraction * 100), elapsed,
                     remaining);
        std::fflush(stderr);
    } else if (style_ == ProgressStyle::kLines) {
        const int decile = int(fraction * 10);
        if (decile > last_decile_ && decile < 10) {
            std::fprintf(stderr, "progress: %d%% (elapsed %.1fs, remaining %.1fs)\n", decile * 10, elapsed,
                         remaining);
            last_decile_ = decile;
        }
    }
}

void Progress::clear() {
    if (style_ == ProgressStyle::kBar) std::fprintf(stderr, "\r%*s\r", 72, "");
}

}  // namespace rt
