#include "rt/core/effect_set.hpp"

namespace rt {

std::string EffectSet::to_string() const {
    std::string text;
    for (int i = 0; i < kEffectCount; ++i) {
        if (!contains(Effect(i))) continue;
        if (!text.empty()) text += ", ";
        text += kEffectNames[std::size_t(i)];
    }
    return text.empty() ? "none" : text;
}

std::optional<Effect> effect_from_name(std::string_view name) {
    for (int i = 0; i < kEffectCount; ++i) {
        if (kEffectNames[std::size_t(i)] == name) return Effect(i);
    }
    return std::nullopt;
}

}  // namespace rt
