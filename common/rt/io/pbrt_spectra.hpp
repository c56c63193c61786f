// pbrt-v4's named metal spectra ("spectrum eta" "metal-Cu-eta"), as the RGB values the course renders with:
// the measured spectra integrated against the linear sRGB primaries, as tabulated in Tungsten's
// ComplexIorData.hpp (B. Bitterli). Gold, copper and aluminium are the course's conductor presets
// (conductor_presets.hpp); silver is that table's entry "Ag".
#pragma once

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

inline constexpr std::string_view kPbrtNamedSpectra =
    "metal-Ag-eta, metal-Ag-k, metal-Al-eta, metal-Al-k, metal-Au-eta, metal-Au-k, metal-Cu-eta, metal-Cu-k";

}  // namespace rt
