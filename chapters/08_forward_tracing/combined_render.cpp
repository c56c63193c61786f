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

    // The light paths draw from streams of their own seed, not the camera samples' (path i and pixel i
    // would otherwise share their numbers). The live view follows the camera's passes only.
    RenderSettings light_settings = settings;
    light_settings.seed = settings.seed ^ 0x9e3779b97f4a7c15ULL;
    light_settings.observer = nullptr;
    // R × W × H light paths for each camera sample of every pixel.
    const auto light_paths_for = [&](int samples) {
        const std::uint64_t camera_paths =
            std::uint64_t(samples) * std::uint64_t(settings.width) * std::uint64_t(settings.height);
        return std::uint64_t(std::llround(double(options.light_paths_per_sample) * double(camera_paths)));
    };
    const std::uint64_t light_paths = light_paths_for(settings.samples_per_pixel);

    CombinedResult r;
    r.split = split;
    if (!split || light_paths == 0) {
        r.paths = split ? render_paths(paths, camera, settings, CameraCausticCut(options.caustic_bounces))
                        : render_paths(paths, camera, settings);
        r.render = r.paths;
        r.render.sums = {};  // the sum is no longer the mean of pixel samples: it has no film
        return r;
    }
    // The light paths are traced between the camera's passes: before the pass that ends at sample `end`,
    // those of camera samples 0 … end − 1 (in whole waves of chunks, so the same bits as traced all after).
    // An interrupt then leaves the light paths of at least the camera samples kept: each half is an unbiased
    // estimate of its part of the image (of any number of its samples), and the partial image estimates the
    // whole, caustics included, where the camera's part alone was 2–4 % too dark.
    SplatRender caustics(light_settings, light_paths, light_paths_of(light));
    RenderSettings camera_settings = settings;
    camera_settings.before_pass = [&](int end) { caustics.trace_until(light_paths_for(end)); };
    r.paths = render_paths(paths, camera, camera_settings, CameraCausticCut(options.caustic_bounces));
    r.caustics = caustics.result();
    r.paths.seconds -= r.caustics.render.seconds;  // its time held the light paths' too
    r.render = r.paths;
    r.render.sums = {};
    // A pixel the camera has no sample of (interrupted in the first pass) stays black, as the summary says.
    const std::vector<Color>& caustic = r.caustics.render.image.pixels();
    const std::vector<PixelSum>& camera_sums = r.paths.sums.pixels();
    for (std::size_t p = 0; p < caustic.size(); ++p)
        if (camera_sums[p].count > 0) r.render.image.pixels()[p] += caustic[p];
    r.render.rays += r.caustics.render.rays;
    r.render.seconds += r.caustics.render.seconds;
    r.render.interrupted = r.paths.interrupted || r.caustics.render.interrupted;
    return r;
}

}  // namespace rt
