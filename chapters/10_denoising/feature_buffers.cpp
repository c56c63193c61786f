#include "feature_buffers.hpp"

#include "01_ray_generation/camera.hpp"
#include "01_ray_generation/camera_render.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "06_monte_carlo/render_paths.hpp"
#include "09_participating_media/volume_path_tracer.hpp"
#include "path_features.hpp"

namespace rt {

FeatureRender render_features(const Scene& scene, const RenderSettings& settings, PathOptions options) {
    const RenderScene prepared(scene, options.simulated, media_materials());
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    const VolumePathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    // Layers beside the image: L², albedo, albedo², normal, normal², depth, depth².
    std::array<PixelSums, 7> layers;
    FeatureRender out;
    out.result = render_layers(settings, layers, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        PathFeatures f;
        // The sample chapter 06's render_paths would trace: the noisy image is chapter 09's, to the bit.
        const Color L = sample_radiance(tracer, camera, settings, s, rng, rays, &f);
        const Color n(f.normal), d(f.depth);
        return std::array<Color, 8>{L, L * L, f.albedo, f.albedo * f.albedo, n, n * n, d, d * d};
    });
    FeatureBuffers& b = out.buffers;
    b.colour = out.result.image;
    b.colour_variance = variance_image(out.result.sums, layers[0]);
    b.albedo = layers[1].mean_image();
    b.albedo_variance = variance_image(layers[1], layers[2]);
    b.normal = layers[3].mean_image();
    b.normal_variance = variance_image(layers[3], layers[4]);
    b.depth = layers[5].mean_image();
    b.depth_variance = variance_image(layers[5], layers[6]);
    return out;
}

}  // namespace rt
