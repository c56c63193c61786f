// pbrt-v4's named metal spectra ("spectrum eta" "metal-Cu-eta"), as the RGB values the course renders with:
// the measured spectra integrated against the linear sRGB primaries, as tabulated in Tungsten's
// ComplexIorData.hpp (B. Bitterli). Gold, copper and aluminium are the course's conductor presets
// (conductor_presets.hpp); silver is that table's entry "Ag". And a blackbody's colour ("blackbody L" 3000).
#pragma once

#include <glm/common.hpp>
#include <optional>
#include <string_view>

#include "rt/core/conductor_presets.hpp"
#include "rt/core/math.hpp"

namespace rt {

// The RGB value of a named metal spectrum "metal-X-eta" or "metal-X-k" (X: Ag, Al, Au, Cu), or nothing.
inline std::optional<Vec3d> pbrt_named_spectrum(std::string_view name) {
    struct Metal {
        std::string_view symbol;
        Vec3d eta, k;
    };
    auto preset = [](std::string_view symbol, std::string_view preset_name) {
        for (const ConductorPreset& p : kConductorPresets) {
            if (p.name == preset_name) return Metal{symbol, Vec3d(p.eta), Vec3d(p.k)};
        }
        return Metal{};
    };
    const Metal metals[] = {
        {"Ag", {0.1552646489, 0.1167232965, 0.1383806959}, {4.8283433224, 3.1222459278, 2.1469504455}},
        preset("Al", "aluminium"), preset("Au", "gold"), preset("Cu", "copper")};
    for (const Metal& m : metals) {
        const std::string prefix = "metal-" + std::string(m.symbol) + "-";
        if (name == prefix + "eta") return m.eta;
        if (name == prefix + "k") return m.k;
    }
    return std::nullopt;
}

// The temperatures pbrt_blackbody_rgb converts, in kelvin: the range of Kim et al.'s fit.
inline constexpr double kBlackbodyLeast = 1667, kBlackbodyMost = 25000;

// A blackbody of `kelvin` (in [kBlackbodyLeast, kBlackbodyMost]) as linear sRGB of luminance Y = 1: pbrt-v4
// divides a light's spectrum by its luminance, so "blackbody L" T is that colour at 1 nit, as "rgb L"
// [1 1 1] is white at 1 nit. Its CIE 1931 chromaticity (x, y) is Kim, Kang, Kim, Lee and Kang's cubic fit of
// the Planckian locus (IEEE Trans. Consumer Electronics 48(3), 2002; also Wikipedia, "Planckian locus"),
// within about 10⁻³ of the integral of Planck's law against the colour-matching functions; XYZ = (x/y, 1,
// (1 − x − y)/y) goes to linear sRGB by IEC 61966-2-1's matrix. A channel below 0 (outside the sRGB gamut,
// blue below about 1900 K) is clipped to 0.
inline Vec3d pbrt_blackbody_rgb(double kelvin) {
    const double t = 1e3 / kelvin, t2 = t * t, t3 = t2 * t;  // in 1000 K⁻¹
    const double x = kelvin <= 4000 ? -0.2661239 * t3 - 0.2343589 * t2 + 0.8776956 * t + 0.179910
                                    : -3.0258469 * t3 + 2.1070379 * t2 + 0.2226347 * t + 0.240390;
    const double x2 = x * x, x3 = x2 * x;
    const double y = kelvin <= 2222   ? -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683
                     : kelvin <= 4000 ? -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867
                                      : 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
    const double X = x / y, Y = 1, Z = (1 - x - y) / y;
    const Vec3d rgb(3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z,
                    -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
                    0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z);
    return glm::max(rgb, Vec3d(0));
}

inline constexpr std::string_view kPbrtNamedSpectra =
    "metal-Ag-eta, metal-Ag-k, metal-Al-eta, metal-Al-k, metal-Au-eta, metal-Au-k, metal-Cu-eta, metal-Cu-k";

}  // namespace rt
