#include "rt/image_io.hpp"

#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "rt/errors.hpp"

namespace rt {
namespace fs = std::filesystem;

Real srgb_encode(Real linear) {
    const Real c = std::clamp(linear, Real(0), Real(1));
    return c <= Real(0.0031308) ? Real(12.92) * c : Real(1.055) * std::pow(c, Real(1) / Real(2.4)) - Real(0.055);
}

std::uint8_t to_display_byte(Real linear) {
    if (!std::isfinite(linear)) linear = 0;
    return std::uint8_t(std::lround(srgb_encode(linear) * Real(255)));
}

void check_writable(const fs::path& path) {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
        throw InputError(path.string() + ": output folder " + folder.string() + " does not exist");
    }
    if (::access(folder.c_str(), W_OK) != 0) {
        throw InputError(path.string() + ": output folder " + folder.string() + " is not writable");
    }
}

namespace {

// Writes through `write_to(temporary)` then renames over `path`: all or nothing.
void write_atomically(const fs::path& path, const std::function<bool(const fs::path&)>& write_to) {
    check_writable(path);
    const fs::path temporary = path.string() + ".partial-" + std::to_string(::getpid());
    const bool ok = write_to(temporary);
    std::error_code ec;
    if (!ok) {
        fs::remove(temporary, ec);
        throw std::runtime_error(path.string() + ": could not write the file (disk full or I/O error)");
    }
    fs::rename(temporary, path, ec);
    if (ec) {
        fs::remove(temporary, ec);
        throw std::runtime_error(path.string() + ": could not rename the finished file: " + ec.message());
    }
}

}  // namespace

void write_png(const Image& image, const fs::path& path) {
    std::vector<std::uint8_t> bytes(image.pixel_count() * 3);
    std::size_t i = 0;
    for (const Color& c : image.pixels()) {
        bytes[i++] = to_display_byte(c.r);
        bytes[i++] = to_display_byte(c.g);
        bytes[i++] = to_display_byte(c.b);
    }
    write_atomically(path, [&](const fs::path& temporary) {
        return stbi_write_png(temporary.c_str(), image.width(), image.height(), 3, bytes.data(),
                              image.width() * 3) != 0;
    });
}

// PFM: "PF\n<width> <height>\n<scale>\n" then float RGB rows from the bottom up; a negative scale is
// little-endian.
void write_pfm(const Image& image, const fs::path& path) {
    write_atomically(path, [&](const fs::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << "PF\n" << image.width() << ' ' << image.height() << "\n-1.0\n";
        for (int y = image.height() - 1; y >= 0; --y) {
            for (int x = 0; x < image.width(); ++x) {
                const Color& c = image.at(x, y);
                const float rgb[3] = {float(c.r), float(c.g), float(c.b)};
                out.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
            }
        }
        out.flush();
        return bool(out);
    });
}

Image read_pfm(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot open the file for reading");
    std::string magic;
    long width = 0, height = 0;
    double scale = 0;
    in >> magic >> width >> height >> scale;
    if (!in || magic != "PF") throw InputError(path.string() + ": not a colour PFM file (expected \"PF\")");
    if (width <= 0 || height <= 0 || width > 1 << 16 || height > 1 << 16 || scale == 0 || !std::isfinite(scale)) {
        throw InputError(path.string() + ": bad PFM header");
    }
    in.get();  // the single whitespace after the scale
    const bool file_little_endian = scale < 0;
    const bool swap = file_little_endian != (std::endian::native == std::endian::little);
    Image image{int(width), int(height)};
    for (int y = image.height() - 1; y >= 0; --y) {
        for (int x = 0; x < image.width(); ++x) {
            float rgb[3];
            in.read(reinterpret_cast<char*>(rgb), sizeof rgb);
            if (!in) throw InputError(path.string() + ": truncated PFM data");
            if (swap) {
                for (float& v : rgb) {
                    std::uint32_t bits;
                    std::memcpy(&bits, &v, 4);
                    bits = __builtin_bswap32(bits);
                    std::memcpy(&v, &bits, 4);
                }
            }
            image.at(x, y) = Color(rgb[0], rgb[1], rgb[2]);
        }
    }
    return image;
}

}  // namespace rt
