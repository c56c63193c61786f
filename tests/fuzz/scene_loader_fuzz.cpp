// libFuzzer target for the scene loader: any bytes given to parse_scene either load into a scene that keeps
// the loader's promises, or raise an InputError with a one-line message that starts with the file name.
// Anything else (another exception, a crash, a sanitizer report, a broken promise) is a bug the fuzzer
// reports. Build with the "fuzz" preset; .ci/run runs it with every scene in assets/scenes as seeds.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>

#include "rt/io/effects.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/scene_loader.hpp"

namespace {

// Inside the course's scene folder, so relative mesh paths in the seeds ("../meshes/...") resolve.
const std::string kFile = std::string(RT_ASSETS_DIR) + "/scenes/fuzz_input.json";

[[noreturn]] void broken(const char* promise) {
    std::fprintf(stderr, "scene_loader_fuzz: a loaded scene breaks a promise: %s\n", promise);
    std::abort();
}

void expect(bool holds, const char* promise) {
    if (!holds) broken(promise);
}

bool finite_and_bounded(const rt::Vec3& v) {
    return rt::is_finite(v) && glm::length(v) < 1e10f;
}

// What a scene that loaded promises to every chapter.
void check_scene(const rt::Scene& scene) {
    using namespace rt;
    const CameraDesc& c = scene.camera;
    expect(finite_and_bounded(c.from) && finite_and_bounded(c.at), "camera.from and camera.at are finite");
    expect(is_finite(glm::normalize(c.at - c.from)), "at - from can be normalised");
    expect(is_finite(glm::normalize(c.up)), "up can be normalised");
    expect(!parallel(Vec3d(c.at - c.from), Vec3d(c.up)), "up is not parallel to the view direction");
    expect(c.vfov > 0 && c.vfov < 180, "vfov is in (0, 180)");
    expect(scene.image.width >= 1 && scene.image.height >= 1 && scene.image.spp >= 1,
           "image sizes are positive");
    for (const Material& m : scene.materials) {
        expect(is_finite(m.albedo) && is_finite(m.emission) && is_finite(m.reflectance),
               "colours are finite");
        expect(m.emission.r >= 0 && m.emission.g >= 0 && m.emission.b >= 0, "emission is not negative");
    }
    for (const Shape& s : scene.shapes) {
        expect(s.material >= 0 && std::size_t(s.material) < scene.materials.size(),
               "a shape's material exists");
        if (const auto* sphere = std::get_if<SphereShape>(&s.geometry)) {
            expect(sphere->radius > 0 && std::isfinite(sphere->radius), "a sphere's radius is positive");
            expect(finite_and_bounded(sphere->center), "a sphere's center is finite");
        } else if (const auto* quad = std::get_if<QuadShape>(&s.geometry)) {
            expect(is_finite(glm::normalize(glm::cross(quad->u, quad->v))),
                   "a quad's normal can be normalised");
        } else if (const auto* triangle = std::get_if<TriangleShape>(&s.geometry)) {
            const auto& v = triangle->vertices;
            expect(is_finite(glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]))),
                   "a triangle's normal can be normalised");
        } else if (const auto* plane = std::get_if<PlaneShape>(&s.geometry)) {
            expect(is_finite(glm::normalize(plane->normal)), "a plane's normal can be normalised");
        } else if (const auto* mesh = std::get_if<MeshShape>(&s.geometry)) {
            expect(!mesh->triangles.empty(), "a mesh has triangles");
            for (const auto& t : mesh->triangles) {
                for (const std::uint32_t i : t)
                    expect(i < mesh->positions.size(), "a mesh's indices are in range");
            }
            for (const Vec3& p : mesh->positions)
                expect(finite_and_bounded(p), "a mesh's vertices are finite");
        }
    }
    for (const PointLight& light : scene.point_lights) {
        expect(finite_and_bounded(light.position) && is_finite(light.intensity), "a point light is finite");
    }
    needed(scene);  // must not throw
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        check_scene(rt::parse_scene(text, kFile));
    } catch (const rt::InputError& e) {
        const std::string message = e.what();
        expect(message.find('\n') == std::string::npos, "an error message is one line");
        expect(message.rfind(kFile + ": ", 0) == 0, "an error message starts with the file's name");
    }
    return 0;
}
