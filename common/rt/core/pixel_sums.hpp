// Exact per-pixel sums of samples. Each channel of each sample is turned into whole numbers of units and
// added into 128-bit integers: integer addition is exact, so the sums are the same bits whatever order the
// samples are added in, on one thread or many, in one run or in pieces merged later (rt_merge), in one process
// or many (MPI). A pixel's value is then its sum over its sample count, rounded once.
//
// Range: every finite float. A channel v is split exactly into its part of 2^50 and above, counted in units of
// 2^50 (at most 2^78 a sample), and the rest, counted in units of 2^-56 (truncated toward zero, at most 2^106
// a sample): kMaxSamplesPerPixel (2^20) samples stay inside 128 bits in both. A sample below 2^50 (the fast
// path below 2^7 included) has no high part and adds exactly what it did before the split. A sample of 2^128
// or more (only a double build computes one) is beyond the sums and counts as infinite; NaN and infinite
// samples are kept as flags, which make the pixel NaN or infinite as floating-point addition would (and the
// run then fails: no image may hold one).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rt/core/image.hpp"
#include "rt/core/math.hpp"

namespace rt {

__extension__ typedef __int128 Int128;

inline constexpr int kSumFractionBits = 56;
inline constexpr double kHighUnit = 0x1p50;      // the unit of a sample's high part
inline constexpr double kSampleLimit = 0x1p128;  // every sample is below it in magnitude, or counts as infinite

// One pixel's samples summed exactly.
struct PixelSum {
    // Flags of `non_finite`, for channel c shifted left by 3c.
    static constexpr std::uint32_t kNan = 1, kPlusInfinity = 2, kMinusInfinity = 4, kAllFlags = 0777;

    std::array<Int128, 3> channels{};  // Σ samples' parts below kHighUnit, in units of 2^-kSumFractionBits
    std::array<Int128, 3> high{};      // Σ samples' parts of kHighUnit and above, in units of kHighUnit
    std::uint32_t count = 0;           // samples summed
    std::uint32_t non_finite = 0;      // flags of the samples that were NaN or infinite

    void add(const Color& sample) {
        const double r = double(sample.r), g = double(sample.g), b = double(sample.b);
        // The common case, every channel below 2^7 in magnitude (NaN fails the test): its units fit 64 bits.
        if (std::fabs(r) < 0x1p7 && std::fabs(g) < 0x1p7 && std::fabs(b) < 0x1p7) {
            channels[0] += std::int64_t(r * 0x1p56);
            channels[1] += std::int64_t(g * 0x1p56);
            channels[2] += std::int64_t(b * 0x1p56);
        } else {
            for (int c = 0; c < 3; ++c) add_channel(c, double(sample[c]));
        }
        ++count;
    }
    void add(const PixelSum& other) {
        for (std::size_t c = 0; c < 3; ++c) {
            channels[c] += other.channels[c];
            high[c] += other.high[c];
        }
        count += other.count;
        non_finite |= other.non_finite;
    }
    // Channel c's sum, in double.
    double total(int c) const;
    // The sum over the count (0 for no sample), rounded to Real.
    Color mean() const;
    bool operator==(const PixelSum&) const = default;

  private:
    void add_channel(int c, double value) {
        if (!(std::fabs(value) < kSampleLimit)) {
            const std::uint32_t flag = std::isnan(value) ? kNan : value > 0 ? kPlusInfinity : kMinusInfinity;
            non_finite |= flag << (3 * c);
            return;
        }
        const std::size_t i = std::size_t(c);
        if (std::fabs(value) >= kHighUnit) {  // both parts exact: a multiple of 2^50, and the rest below it
            const double units = std::trunc(value / kHighUnit);
            high[i] += Int128(units);
            value -= units * kHighUnit;
        }
        const double units = value * 0x1p56;
        // Both conversions truncate toward zero; the 64-bit one is a single instruction.
        channels[i] += std::fabs(units) < 0x1p63 ? Int128(std::int64_t(units)) : Int128(units);
    }
};

// A whole image of them, row by row from the top left.
class PixelSums {
  public:
    PixelSums() = default;
    PixelSums(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const { return pixels_.empty(); }
    PixelSum& at(int x, int y) { return pixels_[std::size_t(y) * std::size_t(width_) + std::size_t(x)]; }
    const PixelSum& at(int x, int y) const {
        return pixels_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
    }
    std::vector<PixelSum>& pixels() { return pixels_; }
    const std::vector<PixelSum>& pixels() const { return pixels_; }

    // Adds `other` (of the same size) pixel by pixel.
    void add(const PixelSums& other);
    // Every pixel's mean.
    Image mean_image() const;
    // The fewest samples any pixel has, and all of them together.
    std::uint32_t min_count() const;
    std::uint64_t total_count() const;
    bool operator==(const PixelSums&) const = default;

  private:
    int width_ = 0;
    int height_ = 0;
    std::vector<PixelSum> pixels_;
};

// The variance of a pixel's mean, from the exact sums of its n samples x and of their squares x² (a layer of
// squared samples beside the image, render_layers in render_loop.hpp), per channel:
//   s² = (Σx² − (Σx)²/n) / (n − 1)   (the unbiased sample variance),   Var[mean] = s² / n;
// 0 for fewer than two samples, and never below 0 (the sums are exact; the subtraction is in double).
Color variance_of_mean(const PixelSum& sum, const PixelSum& squares);
// Every pixel's variance of its mean.
Image variance_image(const PixelSums& sums, const PixelSums& squares);

}  // namespace rt
