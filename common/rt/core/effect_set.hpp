// The effects a renderer can simulate, and sets of them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rt {

enum class Effect {
    kCameraRays,      // what the camera sees first: surfaces, emitters, the background
    kShadows,         // shadow rays test whether a light is visible
    kDirect,          // light arriving straight from the lights (the direct term)
    kReflection,      // ideal mirror reflection
    kGlossy,          // glossy and retro-reflective lobes
    kIndirect,        // light that has bounced off other surfaces (diffuse interreflection)
    kRefraction,      // light passing through dielectrics
    kMedia,           // light scattered inside participating media (fog, milk, wax): chapter 09
    kShadingNormals,  // a mesh's vertex normals interpolated across its triangles: chapter 04
};
inline constexpr int kEffectCount = 9;
inline constexpr std::array<std::string_view, kEffectCount> kEffectNames = {
    "camera", "shadows", "direct", "reflection", "glossy", "indirect", "refraction", "media", "shading_normals",
};

class EffectSet {
public:
    constexpr EffectSet() = default;
    constexpr EffectSet(std::initializer_list<Effect> effects) {
        for (Effect e : effects) insert(e);
    }
    static constexpr EffectSet all() {
        EffectSet s;
        s.bits_ = (1u << kEffectCount) - 1;
        return s;
    }

    constexpr void insert(Effect e) { bits_ |= bit(e); }
    constexpr bool contains(Effect e) const { return (bits_ & bit(e)) != 0; }
    constexpr bool empty() const { return bits_ == 0; }
    constexpr EffectSet operator&(EffectSet o) const { return from_bits(bits_ & o.bits_); }
    constexpr EffectSet operator|(EffectSet o) const { return from_bits(bits_ | o.bits_); }
    constexpr EffectSet without(EffectSet o) const { return from_bits(bits_ & ~o.bits_); }
    constexpr bool operator==(const EffectSet&) const = default;

    // "camera, shadows, direct" (or "none").
    std::string to_string() const;

private:
    static constexpr std::uint32_t bit(Effect e) { return 1u << unsigned(e); }
    static constexpr EffectSet from_bits(std::uint32_t b) {
        EffectSet s;
        s.bits_ = b;
        return s;
    }
    std::uint32_t bits_ = 0;
};

// The effect named `name` in a scene's "effects" list, if there is one.
std::optional<Effect> effect_from_name(std::string_view name);

}  // namespace rt
