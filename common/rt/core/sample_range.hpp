// Which samples of each pixel a run takes: samples first … end − 1 of a render of N samples per pixel (the
// half-open range "first:end" of --samples). Sample s of pixel p is seeded from (p, s, seed) whatever range
// it is taken in, so pieces that together cover 0:N make the same image as one render of N.
#pragma once

#include <string>
#include <string_view>

namespace rt {

struct SampleRange {
    int first = 0;
    int end = 0;

    int size() const { return end - first; }
    bool operator==(const SampleRange&) const = default;
};

// "A:B", 0 ≤ A < B ≤ total. Throws InputError with what is wrong ("must be A:B with 0 <= A < B <= 64, got
// 3:3").
SampleRange parse_sample_range(std::string_view text, int total);
std::string to_string(const SampleRange& range);

// Part `index` of `parts` contiguous parts of `whole`, in order, their sizes differing by at most one (the
// first parts are the larger). A part can be empty when there are more parts than samples.
SampleRange split_range(const SampleRange& whole, int parts, int index);

}  // namespace rt
