#include "rt/io/material_kind.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>

namespace rt {
namespace {

// In a deque, so that a kind found stays where it is while later ones are added.
std::deque<MaterialKind>& kinds() {
    static std::deque<MaterialKind> registered = [] {
        std::deque<MaterialKind> course;
        for (MaterialKind& kind : course_material_kinds()) course.push_back(std::move(kind));
        return course;
    }();
    return registered;
}

}  // namespace

bool MaterialKind::takes(std::string_view key) const {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

void register_material_kind(MaterialKind kind) {
    if (find_material_kind(kind.type))
        throw std::logic_error("material type " + kind.type + " registered twice");
    kinds().push_back(std::move(kind));
}

const MaterialKind* find_material_kind(std::string_view type) {
    for (const MaterialKind& kind : kinds()) {
        if (kind.type == type) return &kind;
    }
    return nullptr;
}

std::vector<std::string_view> material_type_names() {
    std::vector<std::string_view> names;
    for (const MaterialKind& kind : kinds()) names.push_back(kind.type);
    return names;
}

const MaterialKind& kind_of(const Material& m) {
    const MaterialKind* kind = find_material_kind(m.type);
    if (!kind) throw std::logic_error("material '" + m.name + "' of unknown type " + m.type);
    return *kind;
}

}  // namespace rt
