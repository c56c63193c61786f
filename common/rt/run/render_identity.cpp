#include "rt/run/render_identity.hpp"

#include <fstream>
#include <sstream>
#include <variant>

#include "rt/core/errors.hpp"
#include "rt/core/fnv_hash.hpp"

namespace rt {

namespace {

template <class T>
std::uint64_t hash_of(const std::vector<T>& values, std::uint64_t hash) {
    return fnv1a(values.data(), values.size() * sizeof(T), hash);
}

}  // namespace

std::uint64_t scene_fingerprint(const Scene& scene, const std::filesystem::path& scene_file) {
    std::ifstream in(scene_file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw InputError(scene_file.string() + ": cannot be read again to fingerprint it");
    std::uint64_t hash = fnv1a(text.str());
    for (const Shape& shape : scene.shapes) {
        if (const auto* mesh = std::get_if<MeshShape>(&shape.geometry)) {
            hash = hash_of(mesh->positions, hash);
            hash = hash_of(mesh->triangles, hash);
            hash = hash_of(mesh->normals, hash);
            hash = hash_of(mesh->normal_corners, hash);
            hash = hash_of(mesh->texture_coordinates, hash);
            hash = hash_of(mesh->texture_corners, hash);
        }
    }
    if (scene.environment && scene.environment->image)
        hash = hash_of(scene.environment->image->pixels(), hash);
    for (const Material& m : scene.materials) {
        for (const Material::Textured& textured : m.textures) {
            const auto* texture = std::get_if<ImageTextureDesc>(&textured.texture.pattern);
            if (!texture) continue;
            const int size[2] = {texture->image->width, texture->image->height};
            hash = fnv1a(size, sizeof size, hash);
            hash = hash_of(texture->image->texels, hash);
        }
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
