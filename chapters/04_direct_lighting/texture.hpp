// Textures: a colour that varies over a surface, looked up at the texture coordinates uv of a hit (Hit::uv,
// chapter 02). An image is a grid of W × H texels in linear RGB (decoded from sRGB when the scene was loaded,
// rt/io/texture_image.hpp); texel (i, j), column i from the left and row j from the top, covers the square
// [i, i + 1] × [j, j + 1] of the image plane, and its value sits at its centre. The point (u, v) of the
// surface, scaled by (su, sv), lands at x = su·u·W, y = (1 − sv·v)·H: v grows up the picture, as in OpenGL.
//   nearest:   the texel whose square holds (x, y);
//   bilinear:  the four texels around it weighted by area: with x − ½ = i + fx, y − ½ = j + fy,
//              (1 − fx)(1 − fy) t(i, j) + fx (1 − fy) t(i+1, j) + (1 − fx) fy t(i, j+1) + fx fy t(i+1, j+1).
// A coordinate outside [0, 1) repeats (i mod W) or clamps to the edge (i in [0, W − 1]), per "wrap".
// The checkerboard: even where ⌊s·u⌋ + ⌊s·v⌋ is even, odd elsewhere (pbrt's Checkerboard).
#pragma once

#include "rt/core/math.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// The texel index a (possibly out-of-range) column or row i reads in a side of n texels.
int wrap_texel(int i, int n, TextureWrap wrap);
// The image's colour at uv, filtered as desc.filter says.
Color image_at(const ImageTextureDesc& desc, Vec2 uv);
// The checker's colour at uv, in double: a plane's coordinates far from the origin (Hit::uv) keep the
// fraction float would round away.
Color checker_at(const CheckerDesc& desc, Vec2d uv);

// Either kind, as the material table holds it.
class Texture {
  public:
    explicit Texture(const TextureDesc& desc) : desc_(desc) {}
    Color at(Vec2d uv) const;

  private:
    TextureDesc desc_;
};

}  // namespace rt
