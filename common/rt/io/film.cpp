#include "rt/io/film.hpp"

#include <bit>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/fnv_hash.hpp"
#include "rt/core/memory_limit.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/staged_file.hpp"

namespace rt {
namespace fs = std::filesystem;
namespace {

std::string format_double(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

static_assert(std::endian::native == std::endian::little, "films are written and read little-endian");

constexpr char kMagic[8] = {'r', 't', '-', 'f', 'i', 'l', 'm', '\n'};
constexpr std::size_t kPixelBytes = 3 * 16 + 3 * 16 + 4 + 4;
constexpr std::uint32_t kMaxTextBytes = 1 << 16;

class Writer {
  public:
    template <typename T>
    void put(T value) {
        const auto* p = reinterpret_cast<const unsigned char*>(&value);
        bytes_.insert(bytes_.end(), p, p + sizeof value);
    }
    void put_text(const std::string& text) {
        put(std::uint32_t(text.size()));
        bytes_.insert(bytes_.end(), text.begin(), text.end());
    }
    std::vector<unsigned char>& bytes() { return bytes_; }

  private:
    std::vector<unsigned char> bytes_;
};

class Reader {
  public:
    Reader(const std::vector<unsigned char>& bytes, std::size_t end, std::string name)
        : bytes_(bytes), end_(end), name_(std::move(name)) {}
    template <typename T>
    T get() {
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof value);
        at_ += sizeof value;
        return value;
    }
    std::string get_text(const char* what) {
        const std::uint32_t size = get<std::uint32_t>();
        if (size > kMaxTextBytes) fail(std::string(what) + " is " + std::to_string(size) + " bytes long");
        need(size);
        std::string text(reinterpret_cast<const char*>(bytes_.data() + at_), size);
        at_ += size;
        return text;
    }
    std::size_t left() const { return end_ - at_; }
    [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

  private:
    void need(std::size_t n) const {
        if (left() < n) fail("truncated: it ends inside its header");
    }
    const std::vector<unsigned char>& bytes_;
    std::size_t at_ = sizeof kMagic;
    std::size_t end_;
    std::string name_;
};

int checked_int(Reader& in, const char* what, std::uint32_t low, std::uint32_t high) {
    const std::uint32_t value = in.get<std::uint32_t>();
    if (value < low || value > high) {
        in.fail(std::string(what) + " must be in [" + std::to_string(low) + ", " + std::to_string(high) +
                "], got " + std::to_string(value));
    }
    return int(value);
}

}  // namespace

std::string first_difference(const FilmIdentity& expected, const FilmIdentity& other) {
    auto differ = [](const std::string& what, const std::string& got, const std::string& want) {
        return what + " " + got + ", expected " + want;
    };
    // The texts are a film's, which is input: escaped, so that they stay on the message's one line.
    auto quoted = [](const std::string& s) { return "\"" + printable(s) + "\""; };
    if (other.chapter != expected.chapter)
        return differ("chapter", printable(other.chapter), printable(expected.chapter));
    if (other.scene_hash != expected.scene_hash) {
        return "scene " + printable(other.scene) + " (its files' fingerprint " +
               std::to_string(other.scene_hash) + "), expected " + printable(expected.scene) + " (" +
               std::to_string(expected.scene_hash) + ")";
    }
    if (other.options != expected.options)
        return differ("chapter flags", quoted(other.options), quoted(expected.options));
    if (other.width != expected.width || other.height != expected.height) {
        return differ("size", std::to_string(other.width) + "x" + std::to_string(other.height),
                      std::to_string(expected.width) + "x" + std::to_string(expected.height));
    }
    if (other.samples_per_pixel != expected.samples_per_pixel) {
        return differ("samples per pixel", std::to_string(other.samples_per_pixel),
                      std::to_string(expected.samples_per_pixel));
    }
    if (other.seed != expected.seed)
        return differ("seed", std::to_string(other.seed), std::to_string(expected.seed));
    return "";
}

void check_film_values(const Film& film, const std::string& name) {
    const std::uint32_t samples = std::uint32_t(film.range.size());
    const int width = film.sums.width();
    // Per sample, its part below kHighUnit in units of 2^-kSumFractionBits: at most kHighUnit, and at least
    // −2^-16 (radiance is never negative; a colour computed as (d + 1) / 2 of a unit vector may round a hair
    // below 0); its high part in units of kHighUnit: at most kSampleLimit / kHighUnit, and never negative.
    const Int128 most = Int128(kHighUnit) << kSumFractionBits;
    const Int128 least = -(Int128(1) << (kSumFractionBits - 16));
    const Int128 most_high = Int128(kSampleLimit / kHighUnit);
    for (std::size_t i = 0; i < film.sums.pixels().size(); ++i) {
        const PixelSum& p = film.sums.pixels()[i];
        std::string wrong;
        if (p.count > samples) {
            wrong = "has " + std::to_string(p.count) + " samples, more than the film's " +
                    std::to_string(samples);
        } else if ((p.non_finite & ~PixelSum::kAllFlags) != 0) {
            wrong = "has unknown flags " + std::to_string(p.non_finite);
        } else if (p.non_finite != 0) {
            wrong =
                "holds a NaN or infinite sample: the render that wrote it failed; render this piece again";
        }
        auto outside = [&](std::size_t c, double sum, double low, double high, const std::string& limit) {
            return "has a sum of " + format_double(sum) + " in channel " + std::to_string(c) + " for " +
                   std::to_string(p.count) + " samples, outside [" + format_double(low) + ", " +
                   format_double(high) + "] (radiance is never negative, and " + limit + ")";
        };
        const HighParts high_parts = p.high();
        for (std::size_t c = 0; c < 3 && wrong.empty(); ++c) {
            const Int128 low = p.channels[c], high = high_parts[c], count = p.count;
            if (low < count * least || low > count * most) {
                wrong = outside(c, double(low) * 0x1p-56, double(count * least) * 0x1p-56,
                                double(count * most) * 0x1p-56, "a sample's part below 2^50 is at most 2^50");
            } else if (high < 0 || high > count * most_high) {
                wrong = outside(c, double(high) * kHighUnit, 0, double(count * most_high) * kHighUnit,
                                "a sample is below " + format_double(kSampleLimit) +
                                    "; this is the sum of the samples' parts of 2^50 and above");
            }
        }
        if (!wrong.empty()) {
            throw InputError(name + ": pixel (" + std::to_string(i % std::size_t(width)) + ", " +
                             std::to_string(i / std::size_t(width)) + ") " + wrong);
        }
    }
}

bool encode_film(const Film& film, std::FILE* file) {
    const FilmIdentity& id = film.identity;
    Writer out;
    for (const char c : kMagic) out.put(c);
    out.put(kFilmVersion);
    out.put(std::uint32_t(kSumFractionBits));
    for (int v : {id.width, id.height, id.samples_per_pixel, film.range.first, film.range.end})
        out.put(std::uint32_t(v));
    out.put(id.seed);
    out.put(id.scene_hash);
    out.put_text(id.chapter);
    out.put_text(id.scene);
    out.put_text(id.options);
    out.bytes().reserve(out.bytes().size() + film.sums.pixels().size() * kPixelBytes + 8);
    for (const PixelSum& p : film.sums.pixels()) {
        for (const Int128 c : p.channels) out.put(c);
        for (const Int128 c : p.high()) out.put(c);
        out.put(p.count);
        out.put(p.non_finite);
    }
    out.put(fnv1a(out.bytes().data(), out.bytes().size()));
    return write_bytes(file, out.bytes().data(), out.bytes().size());
}

void write_film(const Film& film, const fs::path& path) {
    StagedFile staged(path);
    write_staged(staged, [&](std::FILE* file) { return encode_film(film, file); });
    staged.commit();
}

Film read_film(const fs::path& path) {
    const std::string name = path.string();
    check_regular_file(path, "a film file");
    std::error_code ec;
    std::ifstream file(path, std::ios::binary);
    const std::uintmax_t size = fs::file_size(path, ec);
    // Its bytes, then its sums (as many bytes again), are held at once.
    if (!ec) check_fits_in_memory(2.0 * double(size), name + ": a film of " + std::to_string(size) + " bytes");
    std::vector<unsigned char> bytes(ec ? 0 : size);
    if (ec || !file.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size())))
        throw InputError(name + ": cannot be read");
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw InputError(name + ": not a film file (it does not start with \"rt-film\")");
    constexpr std::size_t kChecksumBytes = 8;
    Reader header(bytes, bytes.size(), name);
    const auto version = header.get<std::uint32_t>();
    if (version != kFilmVersion) {
        header.fail("film version " + std::to_string(version) + ", this program reads version " +
                    std::to_string(kFilmVersion));
    }
    if (bytes.size() < sizeof kMagic + 4 + kChecksumBytes)
        header.fail("truncated: it ends inside its header");
    const std::size_t body = bytes.size() - kChecksumBytes;
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + body, sizeof stored);
    if (fnv1a(bytes.data(), body) != stored)
        header.fail("corrupt: its checksum does not match its contents (the file is damaged or truncated)");

    Reader in(bytes, body, name);
    in.get<std::uint32_t>();  // the version, read above
    const auto fraction_bits = in.get<std::uint32_t>();
    if (fraction_bits != std::uint32_t(kSumFractionBits)) {
        in.fail("sums in units of 2^-" + std::to_string(fraction_bits) + ", this program adds units of 2^-" +
                std::to_string(kSumFractionBits));
    }
    Film film;
    FilmIdentity& id = film.identity;
    id.width = checked_int(in, "width", 1, kMaxImageSide);
    id.height = checked_int(in, "height", 1, kMaxImageSide);
    id.samples_per_pixel = checked_int(in, "samples per pixel", 1, kMaxSamplesPerPixel);
    film.range.first = checked_int(in, "first sample", 0, std::uint32_t(id.samples_per_pixel - 1));
    film.range.end = checked_int(in, "end sample", std::uint32_t(film.range.first + 1),
                                 std::uint32_t(id.samples_per_pixel));
    id.seed = in.get<std::uint64_t>();
    id.scene_hash = in.get<std::uint64_t>();
    id.chapter = in.get_text("the chapter's name");
    id.scene = in.get_text("the scene's name");
    id.options = in.get_text("the chapter's flags");
    const std::size_t pixels = std::size_t(id.width) * std::size_t(id.height);
    if (in.left() != pixels * kPixelBytes) {
        in.fail("pixel data must be " + std::to_string(pixels * kPixelBytes) + " bytes for " +
                std::to_string(id.width) + "x" + std::to_string(id.height) + ", got " +
                std::to_string(in.left()));
    }
    film.sums = PixelSums(id.width, id.height);
    for (std::size_t i = 0; i < pixels; ++i) {
        PixelSum& p = film.sums.pixels()[i];
        for (Int128& c : p.channels) c = in.get<Int128>();
        HighParts high;
        for (Int128& c : high) c = in.get<Int128>();
        p.add_high(high);
        p.count = in.get<std::uint32_t>();
        p.non_finite = in.get<std::uint32_t>();
    }
    check_film_values(film, name);
    return film;
}

}  // namespace rt
