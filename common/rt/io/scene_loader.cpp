#include "rt/io/scene_loader.hpp"

#include <map>
#include <string_view>
#include <variant>
#include <vector>

#include "rt/io/input_file.hpp"
#include "rt/io/json_reader.hpp"
#include "rt/io/pbrt_reader.hpp"
#include "rt/io/scene_lights.hpp"
#include "rt/io/scene_materials.hpp"
#include "rt/io/scene_node.hpp"
#include "rt/io/scene_shapes.hpp"

namespace rt {
namespace {

namespace fs = std::filesystem;
using namespace scene_reading;

constexpr std::string_view kTopKeys[] = {"description", "camera", "image",   "materials", "shapes",
                                         "lights",      "medium", "effects", "max_depth"};
constexpr std::string_view kCameraKeys[] = {"from", "at", "up", "vfov", "aperture", "focus_distance",
                                            "mirrored"};
constexpr std::string_view kImageKeys[] = {"width", "height", "spp"};

CameraDesc read_camera(const Node& node) {
    node.expect_object(kCameraKeys);
    CameraDesc camera;
    camera.from = node["from"].vec3();
    camera.at = node["at"].vec3();
    if (node.has("up")) camera.up = node["up"].direction();
    if (node.has("vfov")) camera.vfov = node["vfov"].real_in(0, 180, true, true);
    if (node.has("aperture")) camera.aperture = node["aperture"].real_in(0, kLargestNumber, false, false);
    if (node.has("focus_distance")) camera.focus_distance = node["focus_distance"].positive();
    if (node.has("mirrored")) camera.mirrored = node["mirrored"].boolean();
    if (!normalisable(camera.at - camera.from)) {
        node["at"].fail("must differ from camera.from, so that at - from is a direction, got at - from = " +
                        show(camera.at - camera.from));
    }
    if (parallel(Vec3d(camera.at - camera.from), Vec3d(camera.up))) {
        node["up"].fail("must not be parallel to the view direction at - from = " +
                        show(camera.at - camera.from) + ", got " + show(camera.up));
    }
    return camera;
}

ImageDesc read_image(const Node& node) {
    node.expect_object(kImageKeys);
    ImageDesc image;
    if (node.has("width")) image.width = node["width"].integer(1, kMaxImageSide);
    if (node.has("height")) image.height = node["height"].integer(1, kMaxImageSide);
    if (node.has("spp")) image.spp = node["spp"].integer(1, kMaxSamplesPerPixel);
    // Whether width × height fits in memory is checked for the size that will be rendered, which --width and
    // --height may change (app.cpp).
    return image;
}

EffectSet read_effects(const Node& node) {
    EffectSet effects{Effect::kCameraRays};
    for (std::size_t i = 0; i < node.array_size(); ++i) {
        const Node item = node.element(i);
        const std::string name = item.string();
        const auto effect = effect_from_name(name);
        if (!effect) item.fail("unknown effect " + quote(name) + suggestion(name, kEffectNames));
        effects.insert(*effect);
    }
    return effects;
}

// Every file the scene read, in the order its readers opened them, by the same paths: the scene file, the
// materials' textures, the meshes, the environment image (each name joined to the scene's folder).
std::vector<SceneInput> files_read(const Scene& scene, const fs::path& file) {
    const fs::path folder = file.parent_path();
    std::vector<SceneInput> inputs{{"the scene", file}};
    for (const Material& m : scene.materials) {
        for (const Material::Textured& textured : m.textures) {
            const auto* image = std::get_if<ImageTextureDesc>(&textured.texture.pattern);
            if (image)
                inputs.push_back({"the texture of materials." + shown_name(m.name), folder / image->file});
        }
    }
    for (const Shape& shape : scene.shapes) {
        if (const auto* mesh = std::get_if<MeshShape>(&shape.geometry); mesh && !mesh->file.empty())
            inputs.push_back({"the mesh of " + shape.place, folder / mesh->file});
    }
    if (scene.environment && scene.environment->image)
        inputs.push_back({"the environment image", folder / scene.environment->image_file});
    return inputs;
}

}  // namespace

Scene parse_scene(const std::string& text, const fs::path& file) {
    Json root;
    try {
        root = parse_json_strictly(text);
    } catch (const InputError& e) {
        throw InputError(shown(file) + ": " + e.what());
    }
    return read_scene(root, file);
}

Scene read_scene(const nlohmann::json& root, const fs::path& file) {
    const std::string name = shown(file);
    const Node top(root, "", name);
    top.expect_object(kTopKeys);
    if (top.has("description")) top["description"].string();

    Scene scene;
    scene.file = name;
    scene.camera = read_camera(top["camera"]);
    if (top.has("image")) scene.image = read_image(top["image"]);
    if (top.has("max_depth")) scene.max_depth = top["max_depth"].integer(1, kMaxPathDepth);

    std::map<std::string, int> material_index;
    std::vector<std::string_view> material_names;
    const fs::path folder = file.parent_path();  // empty for a bare file name: the current folder
    if (top.has("materials")) {
        const Node materials = top["materials"];
        if (!materials.json().is_object()) materials.fail("must be an object of named materials");
        for (const auto& [key, value] : root.at("materials").items()) {
            material_index[key] = int(scene.materials.size());
            scene.materials.push_back(
                read_material(Node(value, "materials." + shown_name(key), name), key, folder));
        }
        for (const Material& m : scene.materials) material_names.push_back(m.name);
    }
    if (top.has("shapes")) {
        const Node shapes = top["shapes"];
        for (std::size_t i = 0; i < shapes.array_size(); ++i) {
            scene.shapes.push_back(read_shape(shapes.element(i), material_index, folder, material_names));
            if (std::holds_alternative<SphereShape>(scene.shapes.back().geometry) &&
                scene.material_of(scene.shapes.back()).two_sided) {
                shapes.element(i)["material"].fail(
                    "a sphere emits outward only: \"two_sided\" is for quads, "
                    "triangles, boxes and meshes");
            }
        }
    }
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (!used[i]) {
            Node(root, "materials." + shown_name(scene.materials[i].name), name)
                .fail("defined but used by no shape (use it or remove it)");
        }
    }
    if (top.has("lights")) {
        const Node lights = top["lights"];
        for (std::size_t i = 0; i < lights.array_size(); ++i) read_light(lights.element(i), scene, folder);
    }
    if (top.has("medium")) scene.medium = read_medium(top["medium"]);
    if (top.has("effects")) scene.effects = read_effects(top["effects"]);
    scene.inputs = files_read(scene, file);
    return scene;
}

Scene load_scene(const fs::path& file) {
    if (const std::string problem = not_a_regular_file(file); !problem.empty()) {
        throw InputError(shown(file) + ": must be a scene file (JSON or pbrt-v4), got " + problem);
    }
    if (is_pbrt_file(file)) {
        PbrtTranslation translation = translate_pbrt(file);
        Scene scene = read_scene(translation.scene, file);
        scene.notes = std::move(translation.notes);
        for (const fs::path& part : translation.included) {
            scene.inputs.insert(scene.inputs.begin() + 1, SceneInput{"a file the scene includes", part});
        }
        return scene;
    }
    std::string text;
    try {
        text = read_whole_file(file);
    } catch (const InputError& e) {
        throw InputError(shown(file) + ": " + e.what());
    }
    return parse_scene(text, file);
}

}  // namespace rt
