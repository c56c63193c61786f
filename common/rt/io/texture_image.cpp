#include "rt/io/texture_image.hpp"

#include <stb_image.h>

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/input_file.hpp"
#include "rt/io/png_check.hpp"

namespace rt {

namespace {

// What a file's first bytes say it is: "PNG", "JPEG", another kind stb_image would also decode, or neither.
std::string kind_of_image(std::string_view bytes) {
    constexpr std::array<std::pair<std::string_view, std::string_view>, 8> kKinds{{
        {"\x89PNG\r\n\x1a\n", "PNG"},
        {"\xff\xd8\xff", "JPEG"},
        {"GIF8", "a GIF image"},
        {"BM", "a BMP image"},
        {"P5", "a PGM image"},
        {"P6", "a PPM image"},
        {"#?", "a Radiance HDR image"},
        {"8BPS", "a Photoshop (PSD) image"},
    }};
    for (const auto& [signature, kind] : kKinds) {
        if (bytes.starts_with(signature)) return std::string(kind);
    }
    if (bytes.empty()) return "an empty file";
    return "neither (the file starts with \"" + printable(bytes.substr(0, 8)) + "\")";
}

}  // namespace

TextureImage read_texture_image(const std::filesystem::path& path, bool srgb) {
    if (const std::string problem = not_a_regular_file(path); !problem.empty()) throw InputError(problem);
    const std::string bytes = read_whole_file(path);
    const std::string kind = kind_of_image(bytes);
    if (kind != "PNG" && kind != "JPEG") throw InputError("must be a PNG or JPEG image, got " + kind);
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, int(bytes.size()), &width, &height, &channels)) {
        throw InputError(std::string("must be a PNG or JPEG image, got one stb_image cannot read (") +
                         stbi_failure_reason() + ")");
    }
    if (width > kLargestTextureSide || height > kLargestTextureSide) {
        throw InputError("must be at most " + std::to_string(kLargestTextureSide) +
                         " texels on a side, got " + std::to_string(width) + " x " + std::to_string(height));
    }
    if (kind == "PNG") check_png(bytes);
    const std::unique_ptr<stbi_uc, void (*)(void*)> rgb(
        stbi_load_from_memory(data, int(bytes.size()), &width, &height, &channels, 3), stbi_image_free);
    if (!rgb) {
        throw InputError(std::string("must be a PNG or JPEG image, got one stb_image cannot read (") +
                         stbi_failure_reason() + ")");
    }
    // The 256 values a byte can decode to, computed once.
    std::array<Real, 256> decoded{};
    for (int b = 0; b < 256; ++b) decoded[std::size_t(b)] = srgb ? srgb_decode(Real(b) / 255) : Real(b) / 255;
    TextureImage image{width, height, {}};
    const std::size_t count = std::size_t(width) * std::size_t(height);
    image.texels.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const stbi_uc* t = rgb.get() + 3 * i;
        image.texels.push_back({decoded[t[0]], decoded[t[1]], decoded[t[2]]});
    }
    return image;
}

}  // namespace rt
