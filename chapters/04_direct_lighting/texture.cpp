#include "texture.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace rt {
namespace {

// A scaled coordinate brought into [0, 1]: its fraction (repeat) or clamped (clamp). Done before the
// conversion to texel indices, so a plane's far-away coordinates cannot overflow an int.
Real into_unit(Real s, TextureWrap wrap) {
    return wrap == TextureWrap::kRepeat ? s - std::floor(s) : std::clamp(s, Real(0), Real(1));
}

}  // namespace

int wrap_texel(int i, int n, TextureWrap wrap) {
    return wrap == TextureWrap::kRepeat ? ((i % n) + n) % n : std::clamp(i, 0, n - 1);
}

Color image_at(const ImageTextureDesc& desc, Vec2 uv) {
    const TextureImage& image = *desc.image;
    const int w = image.width, h = image.height;
    auto texel = [&](int i, int j) {
        return image.texels[std::size_t(wrap_texel(j, h, desc.wrap)) * std::size_t(w) +
                            std::size_t(wrap_texel(i, w, desc.wrap))];
    };
    const Real x = into_unit(desc.scale.x * uv.x, desc.wrap) * Real(w);
    const Real y = (1 - into_unit(desc.scale.y * uv.y, desc.wrap)) * Real(h);
    if (desc.filter == TextureFilter::kNearest) return texel(int(std::floor(x)), int(std::floor(y)));
    const Real xs = x - Real(0.5), ys = y - Real(0.5);
    const Real i0 = std::floor(xs), j0 = std::floor(ys);
    const Real fx = xs - i0, fy = ys - j0;
    const int i = int(i0), j = int(j0);
    return (1 - fx) * (1 - fy) * texel(i, j) + fx * (1 - fy) * texel(i + 1, j) +
           (1 - fx) * fy * texel(i, j + 1) + fx * fy * texel(i + 1, j + 1);
}

Color checker_at(const CheckerDesc& desc, Vec2d uv) {
    const double scale = desc.scale;
    const double squares = std::floor(scale * uv.x) + std::floor(scale * uv.y);
    return std::fmod(squares, 2.0) == 0 ? desc.even : desc.odd;
}

Color Texture::at(Vec2d uv) const {
    if (const auto* image = std::get_if<ImageTextureDesc>(&desc_.pattern)) return image_at(*image, Vec2(uv));
    return checker_at(std::get<CheckerDesc>(desc_.pattern), uv);
}

}  // namespace rt
