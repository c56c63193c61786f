#include "shadow_render.hpp"

#include "01_ray_generation/camera_render.hpp"
#include "01_ray_generation/pixel_sampling.hpp"
#include "environment_note.hpp"
#include "point_light.hpp"
#include "rt/io/effects.hpp"
#include "rt/io/material_kind.hpp"
#include "shadow_ray.hpp"

namespace rt {

ShadowOptions shadow_options(const EffectSet& simulated, const RayOffset& offset) {
    return {offset, simulated.contains(Effect::kDirect), simulated.contains(Effect::kShadows)};
}

Ray primary_ray(const PinholeCamera& camera, const PixelSample& s, int spp, Pcg32& rng) {
    const Vec2 film = pixel_sample_point(PixelSampler::kStratified, s.x, s.y, s.index, spp, rng.next_vec2());
    return camera_ray_through(camera, film, [&] { return rng.next_vec2(); });
}

Color point_lights_at(const World& world, const Scene& scene, const Hit& hit, const Color& albedo,
                      const ShadowOptions& options, RayCounts& rays) {
    if (!options.direct || albedo == Color(0)) return Color(0);
    Color irradiance(0);
    for (const PointLight& light : scene.point_lights) {
        const Color e = point_light_irradiance(light, hit.point, hit.normal);
        if (e == Color(0)) continue;  // behind the surface: no shadow ray needed
        if (options.shadows && !visible(world, hit, light.position, options.offset, rays)) continue;
        irradiance += e;
    }
    return lambert_radiance(albedo, irradiance);
}

std::vector<Color> stand_in_albedos(const Scene& scene) {
    std::vector<Color> albedos;
    for (const Material& m : scene.materials) albedos.push_back(stand_in_albedo(m));
    return albedos;
}

Color radiance(const World& world, const Scene& scene, const std::vector<Color>& albedos, const Ray& ray,
               const ShadowOptions& options, RayCounts& rays) {
    const auto hit = world.intersect(ray);
    if (!hit) return scene.environment ? scene.environment->radiance : Color(0);
    const Material& material = scene.materials[std::size_t(hit->material)];
    return material.emission +
           point_lights_at(world, scene, *hit, albedos[std::size_t(hit->material)], options, rays);
}

RenderResult render_shadows(const World& world, const Scene& scene, const PinholeCamera& camera,
                            const ShadowOptions& options, const RenderSettings& settings) {
    const int spp = settings.samples_per_pixel;
    const std::vector<Color> albedos = stand_in_albedos(scene);
    return render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        const Ray ray = primary_ray(camera, s, spp, rng);
        rays.add(RayKind::kCamera);
        return radiance(world, scene, albedos, ray, options, rays);
    });
}

std::vector<std::string> shading_notes(const Scene& scene) {
    std::vector<std::string> notes;
    const std::string lights_from = chapter_that_adds(Effect::kDirect);
    if (scene.has_area_lights()) {
        notes.push_back(
            "emissive shapes are seen by the camera but light nothing: area lights are simulated from " +
            lights_from + " on");
    }
    if (!scene.distant_lights.empty() || !scene.spot_lights.empty()) {
        notes.push_back("distant and spot lights light nothing here: they are simulated from " + lights_from +
                        " on");
    }
    if (scene.environment) {
        notes.push_back(
            "the environment is seen as the background but lights nothing: it is a light source from " +
            lights_from + " on");
    }
    if (const auto note = environment_image_note(scene.environment)) notes.push_back(*note);
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        if (!used[i]) continue;
        const Material& m = scene.materials[i];
        if (!m.textures.empty()) {
            notes.push_back(m.type + " material '" + m.name +
                            "': its texture is shaded as its mean colour here; textures are simulated from "
                            "chapter 04 on");
        }
        const auto effect = effect_of(m);
        if (!effect) continue;
        notes.push_back(m.type + " material '" + m.name +
                        "': shaded as Lambertian here; " + simulated_from(m));
    }
    return notes;
}

}  // namespace rt
