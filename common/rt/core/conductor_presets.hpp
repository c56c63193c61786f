// Named metals for a conductor material ("preset": "gold"): the complex index of refraction η + i k per
// colour channel. The values are the measured spectra that pbrt (metal-Au-eta, metal-Au-k, …) and Mitsuba
// ship, integrated against the linear sRGB primaries, as tabulated in Tungsten's ComplexIorData.hpp
// (B. Bitterli; entries "Au", "Cu" and "Al"). They are RGB averages of a spectrum: a spectral renderer's
// gold differs from them in hue by a few per cent.
#pragma once

#include <array>
#include <string_view>

#include "rt/core/math.hpp"

namespace rt {

struct ConductorPreset {
    std::string_view name;
    Color eta;
    Color k;
};

inline const std::array<ConductorPreset, 3> kConductorPresets = {{
    {"gold", {0.1431189557f, 0.3749570432f, 1.4424785571f}, {3.9831604247f, 2.3857207478f, 1.6032152899f}},
    {"copper", {0.2004376970f, 0.9240334304f, 1.1022119527f}, {3.9129485033f, 2.4528477015f, 2.1421879552f}},
    {"aluminium",
     {1.6574599595f, 0.8803689579f, 0.5212287346f},
     {9.2238691996f, 6.2695232477f, 4.8370012281f}},
}};

// The names, in the order of kConductorPresets, for messages.
inline constexpr std::array<std::string_view, 3> kConductorPresetNames = {"gold", "copper", "aluminium"};

}  // namespace rt
