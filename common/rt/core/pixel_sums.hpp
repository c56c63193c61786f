// Exact per-pixel sums of samples. Each channel of each sample is turned into whole numbers of units and
// added into 128-bit integers: integer addition is exact, so the sums are the same bits whatever order the
// samples are added in, on one thread or many, in one run or in pieces merged later (rt_merge), in one process
// or many (MPI). A pixel's value is then its sum over its sample count, rounded once.
//
// Range: every finite float. A channel v is split exactly into its part of 2^50 and above, counted in units of
// 2^50 (at most 2^78 a sample), and the rest, counted in units of 2^-56 (truncated toward zero, at most 2^106
// a sample): kMaxSamplesPerPixel (2^20) samples stay inside 128 bits in both. A sample below 2^50 (the fast
// path below 2^7 included) has no high part and adds exactly what it did before the split; the high parts are
// kept out of line, allocated for the (rare) pixel that has one, so a pixel's sum stays 64 bytes. A sample of 2^128
// or more (only a double build computes one) is beyond the sums and counts as infinite; NaN and infinite
// samples are kept as flags, which make the pixel NaN or infinite as floating-point addition would (and the
// run then fails: no image may hold one).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "rt/core/image.hpp"
#include "rt/core/math.hpp"

namespace rt {

__extension__ typedef __int128 Int128;

inline constexpr int kSumFractionBits = 56;
inline constexpr double kHighUnit = 0x1p50;      // the unit of a sample's high part
inline constexpr double kSampleLimit = 0x1p128;  // every sample is below it in magnitude, or counts as infinite

// A pixel's sums of its samples' parts of kHighUnit and above, per channel, in units of kHighUnit.
using HighParts = std::array<Int128, 3>;

// One pixel's samples summed exactly.
struct PixelSum {
    // Flags of `non_finite`, for channel c shifted left by 3c.
    static constexpr std::uint32_t kNan = 1, kPlusInfinity = 2, kMinusInfinity = 4, kAllFlags = 0777;

    std::array<Int128, 3> channels{};  // Σ samples' parts below kHighUnit, in units of 2^-kSumFractionBits
    std::uint32_t count = 0;           // samples summed
    std::uint32_t non_finite = 0;      // flags of the samples that were NaN or infinite

    PixelSum() = default;
    PixelSum(const PixelSum& other)
        : channels(other.channels), count(other.count), non_finite(other.non_finite),
          high_(other.high_ ? std::make_unique<HighParts>(*other.high_) : nullptr) {}
    PixelSum(PixelSum&&) noexcept = default;
    PixelSum& operator=(const PixelSum& other) { return *this = PixelSum(other); }
    PixelSum& operator=(PixelSum&&) noexcept = default;

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
        for (std::size_t c = 0; c < 3; ++c) channels[c] += other.channels[c];
        if (other.high_) add_high(*other.high_);
        count += other.count;
        non_finite |= other.non_finite;
    }
    // The sums of the samples' high parts (zeros when none had one).
    HighParts high() const { return high_ ? *high_ : HighParts{}; }
    // Adds to them (a film's, or another process's).
    void add_high(const HighParts& parts) {
        if (parts == HighParts{}) return;
        if (!high_) high_ = std::make_unique<HighParts>();
        for (std::size_t c = 0; c < 3; ++c) (*high_)[c] += parts[c];
    }
    // Takes them out, leaving none (to send the sums to another process as plain bytes).
    HighParts take_high() {
        const HighParts parts = high();
        high_.reset();
        return parts;
    }
    // Channel c's sum, in double.
    double total(int c) const;
    // The sum over the count (0 for no sample), rounded to Real.
    Color mean() const;
    bool operator==(const PixelSum& other) const {
        return channels == other.channels && count == other.count && non_finite == other.non_finite &&
               high() == other.high();
    }

  private:
    std::unique_ptr<HighParts> high_;  // null until a sample of kHighUnit or more is added


    void add_channel(int c, double value) {
        if (!(std::fabs(value) < kSampleLimit)) {
            const std::uint32_t flag = std::isnan(value) ? kNan : value > 0 ? kPlusInfinity : kMinusInfinity;
            non_finite |= flag << (3 * c);
            return;
        }
        const std::size_t i = std::size_t(c);
        if (std::fabs(value) >= kHighUnit) {  // both parts exact: a multiple of 2^50, and the rest below it
            const double units = std::trunc(value / kHighUnit);
            HighParts parts{};
            parts[i] = Int128(units);
            add_high(parts);
            value -= units * kHighUnit;
        }
        const double units = value * 0x1p56;
        // Both conversions truncate toward zero; the 64-bit one is a single instruction.
        channels[i] += std::fabs(units) < 0x1p63 ? Int128(std::int64_t(units)) : Int128(units);
    }
};

static_assert(sizeof(PixelSum) == 64, "a pixel's sum is its low parts, count and flags, and one pointer");

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
