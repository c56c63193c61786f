#include "rt/image_io.hpp"

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

#include "rt/atomic_file.hpp"
#include "rt/errors.hpp"

namespace rt {
namespace fs = std::filesystem;

Real srgb_encode(Real linear) {
    const Real c = std::clamp(linear, Real(0), Real(1));
    return c <= Real(0.0031308) ? Real(12.92) * c
                                : Real(1.055) * std::pow(c, Real(1) / Real(2.4)) - Real(0.055);
}

std::uint8_t to_display_byte(Real linear) {
    if (!std::isfinite(linear)) linear = 0;
    return std::uint8_t(std::lround(srgb_encode(linear) * Real(255)));
}

void check_writable(const fs::path& path) {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const std::string where = path.string() + ": cannot be written: ";
    std::error_code ec;
    if (!fs::exists(folder, ec)) throw InputError(where + "folder " + folder.string() + " does not exist");
    if (!fs::is_directory(folder, ec)) {
        throw InputError(where + folder.string() + " is a file, not a folder");
    }
    if (::access(folder.c_str(), W_OK) != 0) {
        throw InputError(where + "folder " + folder.string() + " is not writable");
    }
    if (fs::is_directory(path, ec)) throw InputError(where + "it is a folder");
}

void write_png(const Image& image, const fs::path& path) {
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
    write_atomically(path, [&](std::FILE* file) {
        Sink sink{file, true};
        const int encoded = stbi_write_png_to_func(
            [](void* context, void* data, int size) {
                auto* s = static_cast<Sink*>(context);
                s->ok = s->ok && write_bytes(s->file, data, std::size_t(size));
            },
            &sink, image.width(), image.height(), 3, bytes.data(), image.width() * 3);
        return encoded != 0 && sink.ok;
    });
}

// PFM: "PF\n<width> <height>\n<scale>\n" then float RGB rows from the bottom up; a negative scale is
// little-endian.
void write_pfm(const Image& image, const fs::path& path) {
    static_assert(std::endian::native == std::endian::little, "the PFM writer marks its data little-endian");
    write_atomically(path, [&](std::FILE* file) {
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
    });
}

void check_regular_file(const fs::path& path, const std::string& kind) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw InputError(path.string() + ": must be " + kind + ", got " +
                         (fs::exists(path, ec) ? "something else (a folder?)" : "no such file"));
    }
}

Image read_pfm(const fs::path& path) {
    const std::string name = path.string();
    check_regular_file(path, "a PFM file");
    std::error_code ec;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name + ": cannot be opened for reading");
    std::string magic;
    long long width = 0, height = 0;
    double scale = 0;
    in.width(3);  // the magic is "PF"; read no more than that of whatever else the file holds
    in >> magic >> width >> height >> scale;
    if (magic != "PF") {
        std::string shown;
        for (char c : magic) shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
        throw InputError(name + ": must be a colour PFM file starting with \"PF\", got \"" + shown + "\"");
    }
    if (!in || width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide || scale == 0 ||
        !std::isfinite(scale)) {
        throw InputError(name + ": PFM header must give a width and height in [1, " +
                         std::to_string(kMaxImageSide) + "] and a non-zero scale, got " +
                         std::to_string(width) + " " + std::to_string(height) + " " + std::to_string(scale));
    }
    in.get();  // the single whitespace after the scale
    // The data must all be there before the image is allocated: a short file with a huge header is refused.
    const auto data_start = in.tellg();
    const auto file_size = fs::file_size(path, ec);
    const unsigned long long needed = (unsigned long long)(width) * (unsigned long long)(height)*12ull;
    if (ec || data_start < 0 || file_size < (unsigned long long)(data_start) + needed) {
        throw InputError(
            name + ": PFM data must be " + std::to_string(needed) + " bytes for " + std::to_string(width) +
            "x" + std::to_string(height) + ", got " +
            std::to_string(ec || data_start < 0 ? 0 : file_size - (unsigned long long)(data_start)) +
            " (truncated)");
    }
    const bool file_little_endian = scale < 0;
    const bool swap = file_little_endian != (std::endian::native == std::endian::little);
    Image image{int(width), int(height)};
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
            if (!is_finite(c)) {
                throw InputError(name + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                 ") must be finite, got " + std::to_string(c.r) + " " + std::to_string(c.g) +
                                 " " + std::to_string(c.b));
            }
            image.at(x, y) = c;
        }
    }
    return image;
}

}  // namespace rt
