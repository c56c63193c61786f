#include "rt/io/environment_image.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/exr_file.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/input_file.hpp"

namespace rt {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string e = path.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

void check_pixel(const std::string& name, const Image& image, int x, int y) {
    const Color& c = image.at(x, y);
    if (!is_finite(c) || c.r < 0 || c.g < 0 || c.b < 0) {
        throw InputError(name + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                         ") must be finite radiance, >= 0");
    }
}

// stb_image reads a truncated Radiance file as if the missing bytes were 0, so the scanlines are walked
// first: after the header's blank line and "-Y H +X W", each scanline is either W flat RGBE pixels or, when
// it starts 2 2 with W, four run-length channels (a count byte: above 128 a run of count − 128 copies of one
// byte, otherwise that many literal bytes).
void check_hdr_complete(const std::string& bytes, const std::string& name, int width, int height) {
    std::size_t at = bytes.find("\n\n");
    if (at != std::string::npos) at = bytes.find('\n', at + 2);
    if (at == std::string::npos) throw InputError(name + ": Radiance HDR header is incomplete");
    ++at;
    const auto truncated = [&] { return InputError(name + ": Radiance HDR data is truncated"); };
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
    const std::size_t row_bytes = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y) {
        if (at + 4 > bytes.size()) throw truncated();
        const bool run_length = width >= 8 && width < 32768 && byte(at) == 2 && byte(at + 1) == 2 &&
                                (std::size_t(byte(at + 2)) << 8 | byte(at + 3)) == std::size_t(width);
        if (!run_length) {
            // stb reads every scanline from here on as flat pixels.
            if (bytes.size() - at < row_bytes * std::size_t(height - y)) throw truncated();
            return;
        }
        at += 4;
        for (int channel = 0; channel < 4; ++channel) {
            for (int x = 0; x < width;) {
                if (at >= bytes.size()) throw truncated();
                const int count = byte(at++);
                const bool run = count > 128;
                const int n = run ? count - 128 : count;
                if (n == 0 || x + n > width) throw InputError(name + ": Radiance HDR scanline is corrupt");
                at += run ? 1 : std::size_t(n);
                if (at > bytes.size()) throw truncated();
                x += n;
            }
        }
    }
}

// Radiance RGBE through stb_image; stb would also read a PNG (and undo a gamma of 2.2), so the file must be
// one stb takes for HDR.
Image read_hdr(const std::filesystem::path& path, const std::string& name) {
    if (!stbi_is_hdr(path.c_str())) throw InputError(name + ": must be a Radiance HDR file (\"#?RADIANCE\")");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info(path.c_str(), &width, &height, &channels)) {
        throw InputError(name + ": must be a Radiance HDR file stb_image can read (" + stbi_failure_reason() +
                         ")");
    }
    try {
        check_image_size(width, height);
        check_hdr_complete(read_whole_file(path), name, width, height);
    } catch (const InputError& e) {
        const std::string what = e.what();
        throw InputError(what.rfind(name, 0) == 0 ? what : name + ": " + what);
    }
    const std::unique_ptr<float, void (*)(void*)> data(stbi_loadf(path.c_str(), &width, &height, &channels, 3),
                                                       stbi_image_free);
    if (!data) {
        throw InputError(name + ": must be a Radiance HDR file stb_image can read (" + stbi_failure_reason() +
                         ")");
    }
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float* p = data.get() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
            image.at(x, y) = Color(p[0], p[1], p[2]);
            check_pixel(name, image, x, y);
        }
    }
    return image;
}

}  // namespace

Image read_environment_image(const std::filesystem::path& path) {
    const std::string name = shown(path);
    const std::string extension = lower_extension(path);
    if (extension != ".hdr" && extension != ".pfm" && extension != ".exr") {
        throw InputError(name + ": must be a .hdr, .pfm or .exr image, got a name ending in " +
                         (extension.empty() ? std::string("no extension") : shown_value(extension)));
    }
    check_regular_file(path, "an environment image");
    if (extension == ".pfm") return read_pfm(path, PfmPixels::kRadiance);
    if (extension == ".hdr") return read_hdr(path, name);
    if (!has_openexr()) {
        throw InputError(name + ": OpenEXR images are not read by this build (install libopenexr-dev and "
                                "configure again), or convert it to .hdr or .pfm");
    }
    return read_exr(path, PfmPixels::kRadiance);
}

}  // namespace rt
