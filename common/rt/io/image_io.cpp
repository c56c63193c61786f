#include "rt/io/image_io.hpp"

#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/input_file.hpp"
#include "rt/io/staged_file.hpp"

namespace rt {
namespace fs = std::filesystem;

Real srgb_encode(Real linear) {
    const Real c = std::clamp(linear, Real(0), Real(1));
    return c <= Real(0.0031308) ? Real(12.92) * c
                                : Real(1.055) * std::pow(c, Real(1) / Real(2.4)) - Real(0.055);
}

Real srgb_decode(Real encoded) {
    const Real c = std::clamp(encoded, Real(0), Real(1));
    return c <= Real(0.04045) ? c / Real(12.92) : std::pow((c + Real(0.055)) / Real(1.055), Real(2.4));
}

std::uint8_t to_display_byte(Real linear) {
    if (!std::isfinite(linear)) linear = 0;
    return std::uint8_t(std::lround(srgb_encode(linear) * Real(255)));
}

void check_writable(const fs::path& path) {
    const StagedFile probe(path);  // the staging file a write would use, created here and removed
    // The name it would be renamed to must be one the folder takes.
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const long longest = ::pathconf(folder.c_str(), _PC_NAME_MAX);
    const std::size_t length = path.filename().native().size();
    if (longest > 0 && length > std::size_t(longest)) {
        throw InputError(shown(path) + ": cannot be written: its name is " + std::to_string(length) +
                         " bytes, longer than the " + std::to_string(longest) + " its folder takes");
    }
}

void check_writable(const std::string& flag, const fs::path& path) {
    try {
        check_writable(path);
    } catch (const InputError& e) {
        throw InputError(flag + ": " + e.what());
    }
}

// The PNG's bytes, tone-mapped and sRGB-encoded, into `file`; false when a write failed.
bool encode_png(const Image& image, std::FILE* file) {
    std::vector<std::uint8_t> bytes(image.pixel_count() * 3);
    std::size_t i = 0;
    for (const Color& c : image.pixels()) {
        bytes[i++] = to_display_byte(c.r);
        bytes[i++] = to_display_byte(c.g);
        bytes[i++] = to_display_byte(c.b);
    }
    // stbi_write_png (to a file name) ignores write errors; encoding through a callback lets us check them.
    struct Sink {
        std::FILE* file;
        bool ok;
    };
    Sink sink{file, true};
    const int encoded = stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* s = static_cast<Sink*>(context);
            s->ok = s->ok && write_bytes(s->file, data, std::size_t(size));
        },
        &sink, image.width(), image.height(), 3, bytes.data(), image.width() * 3);
    return encoded != 0 && sink.ok;
}

// PFM: "PF\n<width> <height>\n<scale>\n" then float RGB rows from the bottom up; a negative scale is
// little-endian.
bool encode_pfm(const Image& image, std::FILE* file) {
    static_assert(std::endian::native == std::endian::little, "the PFM writer marks its data little-endian");
    const std::string header =
        "PF\n" + std::to_string(image.width()) + " " + std::to_string(image.height()) + "\n-1.0\n";
    bool ok = write_bytes(file, header.data(), header.size());
    std::vector<float> row(std::size_t(image.width()) * 3);
    for (int y = image.height() - 1; y >= 0 && ok; --y) {
        for (int x = 0; x < image.width(); ++x) {
            const Color& c = image.at(x, y);
            row[3 * std::size_t(x)] = float(c.r);
            row[3 * std::size_t(x) + 1] = float(c.g);
            row[3 * std::size_t(x) + 2] = float(c.b);
        }
        ok = write_bytes(file, row.data(), row.size() * sizeof(float));
    }
    return ok;
}

void write_png(const Image& image, const fs::path& path) {
    StagedFile png(path);
    write_staged(png, [&](std::FILE* file) { return encode_png(image, file); });
    png.commit();
}

void write_pfm(const Image& image, const fs::path& path) {
    StagedFile pfm(path);
    write_staged(pfm, [&](std::FILE* file) { return encode_pfm(image, file); });
    pfm.commit();
}

void check_regular_file(const fs::path& path, const std::string& kind) {
    if (const std::string problem = not_a_regular_file(path); !problem.empty()) {
        throw InputError(shown(path) + ": must be " + kind + ", got " + problem);
    }
}

namespace {

std::string show_number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", x);
    return text;
}

// A PFM's header: "PF", the width and height, the scale (its sign the byte order), one whitespace byte.
struct PfmHeader {
    long long width = 0, height = 0;
    double scale = 0;
};

PfmHeader read_pfm_header(std::istream& in, const std::string& name) {
    std::string magic;
    PfmHeader h;
    in.width(3);  // the magic is "PF"; read no more than that of whatever else the file holds
    in >> magic >> h.width >> h.height >> h.scale;
    if (magic != "PF") {
        std::string shown;
        for (char c : magic) shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
        throw InputError(name + ": must be a colour PFM file starting with \"PF\", got \"" + shown + "\"");
    }
    if (!in || h.width <= 0 || h.height <= 0 || h.width > kMaxImageSide || h.height > kMaxImageSide ||
        h.scale == 0 || !std::isfinite(h.scale)) {
        throw InputError(name + ": PFM header must give a width and height in [1, " +
                         std::to_string(kMaxImageSide) + "] and a non-zero scale, got " +
                         std::to_string(h.width) + " " + std::to_string(h.height) + " " +
                         show_number(h.scale));
    }
    // The scale's sign gives the byte order; its magnitude, a unit for the pixels, is not read: one other
    // than 1 is refused, not ignored.
    if (std::abs(h.scale) != 1) {
        throw InputError(name +
                         ": PFM header's scale must be 1 or -1 (its sign gives the byte order; no other "
                         "magnitude is read), got " +
                         show_number(h.scale));
    }
    // One whitespace byte ends the header; a CRLF line end would shift every pixel by a byte.
    const int after_scale = in.get();
    if (after_scale == '\r' && in.peek() == '\n') {
        throw InputError(name +
                         ": PFM header must end in one whitespace byte before the pixels, got \"\\r\\n\" "
                         "(a Windows line end)");
    }
    if (!std::isspace(after_scale)) {
        throw InputError(name + ": PFM header must end in one whitespace byte before the pixels");
    }
    return h;
}

// The data must all be there before the image is allocated: a short file with a huge header is refused, and
// so is a size beyond this machine's memory or this process's limit.
void check_pfm_data_size(const fs::path& path, const std::string& name, const PfmHeader& h,
                         std::streamoff data_start) {
    std::error_code ec;
    const auto file_size = fs::file_size(path, ec);
    const unsigned long long needed = (unsigned long long)(h.width) * (unsigned long long)(h.height) * 12ull;
    if (ec || data_start < 0 || file_size < (unsigned long long)(data_start) + needed) {
        throw InputError(
            name + ": PFM data must be " + std::to_string(needed) + " bytes for " + std::to_string(h.width) +
            "x" + std::to_string(h.height) + ", got " +
            std::to_string(ec || data_start < 0 ? 0 : file_size - (unsigned long long)(data_start)) +
            " (truncated)");
    }
    try {
        check_image_size(h.width, h.height);
    } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
    }
}

// The float RGB rows, from the bottom up, each pixel checked as it is read.
Image read_pfm_pixels(std::istream& in, const std::string& name, const PfmHeader& h, PfmPixels pixels) {
    const bool file_little_endian = h.scale < 0;
    const bool swap = file_little_endian != (std::endian::native == std::endian::little);
    Image image{int(h.width), int(h.height)};
    for (int y = image.height() - 1; y >= 0; --y) {
        for (int x = 0; x < image.width(); ++x) {
            float rgb[3];
            in.read(reinterpret_cast<char*>(rgb), sizeof rgb);
            if (!in) throw InputError(name + ": PFM data is truncated");
            if (swap) {
                for (float& v : rgb) {
                    std::uint32_t bits;
                    std::memcpy(&bits, &v, 4);
                    bits = __builtin_bswap32(bits);
                    std::memcpy(&v, &bits, 4);
                }
            }
            const Color c(rgb[0], rgb[1], rgb[2]);
            check_read_pixel(name, c, x, y, pixels);
            image.at(x, y) = c;
        }
    }
    return image;
}

}  // namespace

void check_read_pixel(const std::string& name, const Color& c, int x, int y, PfmPixels pixels) {
    const bool radiance = pixels == PfmPixels::kRadiance;
    if (!is_finite(c) || (radiance && (c.r < 0 || c.g < 0 || c.b < 0))) {
        throw InputError(name + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") must be " +
                         (radiance ? "finite radiance, >= 0" : "finite") + ", got " + show_number(c.r) + " " +
                         show_number(c.g) + " " + show_number(c.b));
    }
}

Image read_pfm(const fs::path& path, PfmPixels pixels) {
    const std::string name = shown(path);
    check_regular_file(path, "a PFM file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name + ": cannot be opened for reading");
    const PfmHeader header = read_pfm_header(in, name);
    check_pfm_data_size(path, name, header, in.tellg());
    return read_pfm_pixels(in, name, header, pixels);
}

}  // namespace rt
