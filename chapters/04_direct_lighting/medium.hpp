// What fills a shape (or the space between the shapes): a medium, the volume counterpart of the Bsdf. The
// material table holds one for each shape that a later chapter fills, and the path loop (chapter 06) asks it
// one thing along a segment it traces through it:
//   transmittance(d):  T(d), the fraction of radiance left after a distance d.
// This chapter fills nothing; chapter 07 fills glass with Beer–Lambert absorption, and chapter 09 adds its
// own interface for media that scatter. As with Bsdf, an interface (not a variant) lets the later chapters
// add their media without this chapter naming them.
#pragma once

#include "rt/core/math.hpp"

namespace rt {

class Medium {
  public:
    virtual ~Medium() = default;
    // The fraction of radiance left after `distance` inside it, per colour channel.
    virtual Color transmittance(Real distance) const = 0;
};

}  // namespace rt
