// The median of measured values (a benchmark's repeated timings): the middle one, or the mean of the two
// middle ones when their number is even. Robust to the outliers a loaded machine makes.
#pragma once

#include <algorithm>
#include <vector>

namespace rt {

inline double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

}  // namespace rt
