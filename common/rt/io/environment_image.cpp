#include "rt/io/environment_image.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>

#ifdef RT_HAVE_OPENEXR
#include <ImfArray.h>
#include <ImfRgbaFile.h>
#endif

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/image_io.hpp"

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
    } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
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

#ifdef RT_HAVE_OPENEXR
Image read_exr(const std::filesystem::path& path, const std::string& name) {
    try {
        Imf::RgbaInputFile file(path.c_str());
        const Imath::Box2i window = file.dataWindow();
        const long long width = (long long)(window.max.x) - window.min.x + 1;
        const long long height = (long long)(window.max.y) - window.min.y + 1;
        check_image_size(width, height);
        Imf::Array2D<Imf::Rgba> pixels(height, width);
        file.setFrameBuffer(&pixels[0][0] - window.min.x - window.min.y * width, 1, std::size_t(width));
        file.readPixels(window.min.y, window.max.y);
        Image image(int(width), int(height));
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const Imf::Rgba& p = pixels[y][x];
                image.at(x, y) = Color(float(p.r), float(p.g), float(p.b));
                check_pixel(name, image, x, y);
            }
        }
        return image;
    } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
    } catch (const std::exception& e) {
        throw InputError(name + ": must be an OpenEXR file it can read (" + printable(e.what()) + ")");
    }
}
#endif

}  // namespace

bool reads_openexr() {
#ifdef RT_HAVE_OPENEXR
    return true;
#else
    return false;
#endif
}

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
#ifdef RT_HAVE_OPENEXR
    return read_exr(path, name);
#else
    throw InputError(name + ": OpenEXR images are not read by this build (install libopenexr-dev and "
                            "configure again), or convert it to .hdr or .pfm");
#endif
}

}  // namespace rt
