#include "rt/run/render_identity.hpp"

#include <fstream>
#include <sstream>
#include <variant>

#include "rt/core/errors.hpp"
#include "rt/core/fnv_hash.hpp"

namespace rt {

std::uint64_t scene_fingerprint(const Scene& scene, const std::filesystem::path& scene_file) {
    std::ifstream in(scene_file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw InputError(scene_file.string() + ": cannot be read again to fingerprint it");
    std::uint64_t hash = fnv1a(text.str());
    for (const Shape& shape : scene.shapes) {
        if (const auto* mesh = std::get_if<MeshShape>(&shape.geometry)) {
            hash = fnv1a(mesh->positions.data(), mesh->positions.size() * sizeof(Vec3), hash);
            hash = fnv1a(mesh->triangles.data(), mesh->triangles.size() * sizeof(mesh->triangles[0]), hash);
        }
    }
    if (scene.environment && scene.environment->image) {
        const std::vector<Color>& pixels = scene.environment->image->pixels();
        hash = fnv1a(pixels.data(), pixels.size() * sizeof(Color), hash);
    }
    return hash;
}

std::string chapter_flags_text(const CLI::App& app, const std::set<std::string>& core) {
    std::string text;
    for (const CLI::Option* option : app.get_options()) {
        const std::string name = option->get_name();
        if (option->count() == 0 || core.contains(name)) continue;
        if (!text.empty()) text += ' ';
        text += name;
        for (std::size_t i = 0; i < option->results().size(); ++i)
            text += (i == 0 ? "=" : ",") + option->results()[i];
    }
    return text;
}

}  // namespace rt
