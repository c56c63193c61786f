#include "combined_render.hpp"

#include <cmath>

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "07_bsdf_refraction/refraction_materials.hpp"
#include "camera_caustic_cut.hpp"
#include "camera_importance.hpp"

namespace rt {

CombinedResult render_combined(const Scene& scene, const EffectSet& simulated, const RenderSettings& settings,
                               const CombinedOptions& options) {
    // One World and one set of lights; a material table for each direction light is carried in.
    const RenderScene prepared(scene, simulated, refraction_materials(Transport::kRadiance));
    const MaterialTable importance(scene, simulated, refraction_materials(Transport::kImportance));
    // Both halves of the partition see through one camera: the light paths' pinhole.
    const PinholeCamera camera = light_tracing_camera(scene, settings.width, settings.height);

    // Light paths start only at area and point lights, and do not cross media: a scene with other light or
    // with a medium is rendered by paths alone.
    const bool split = !prepared.lights.environment && prepared.lights.unsampled.empty() &&
                       !simulated.contains(Effect::kMedia);
    PathOptions path_options = options.paths;
    path_options.simulated = simulated;
    const PathTracer paths(prepared.world, prepared.materials, prepared.lights, path_options);

    LightTracerOptions light_options;
    light_options.simulated = simulated;
    light_options.offset = path_options.offset;
    light_options.paths = LightPathSet::kCaustics;
    light_options.caustic_bounces = options.caustic_bounces;
    const LightTracer light(prepared.world, importance, prepared.lights, camera, light_options);

    CombinedResult r;
    r.split = split;
    r.paths = split ? render_paths(paths, camera, settings, CameraCausticCut(options.caustic_bounces))
                    : render_paths(paths, camera, settings);
    // The light paths draw from streams of their own seed, not the camera samples' (path i and pixel i
    // would otherwise share their numbers). The live view follows the camera's passes only.
    RenderSettings light_settings = settings;
    light_settings.seed = settings.seed ^ 0x9e3779b97f4a7c15ULL;
    light_settings.observer = nullptr;
    const auto light_paths = std::uint64_t(
        std::llround(double(options.light_paths_per_sample) * double(paths_per_image(settings))));
    r.render = r.paths;
    r.render.sums = {};  // the sum is no longer the mean of pixel samples: it has no film
    if (r.paths.interrupted || !split || light_paths == 0) return r;
    r.caustics = render_light_tracing(light, light_settings, light_paths);
    const std::vector<Color>& caustic = r.caustics.render.image.pixels();
    for (std::size_t p = 0; p < caustic.size(); ++p) r.render.image.pixels()[p] += caustic[p];
    r.render.rays += r.caustics.render.rays;
    r.render.seconds += r.caustics.render.seconds;
    r.render.interrupted = r.caustics.render.interrupted;
    return r;
}

}  // namespace rt
