#include "bsdf_render.hpp"

#include "01_ray_generation/camera.hpp"
#include "04_direct_lighting/direct_render.hpp"
#include "04_direct_lighting/render_scene.hpp"
#include "refraction_materials.hpp"

namespace rt {

Renderer choose_renderer(const EffectSet& simulated) {
    if (simulated.without(kDirectRendererEffects).empty()) return Renderer::kDirect;
    return Renderer::kPaths;
}

RenderResult render_with(Renderer renderer, const Scene& scene, const EffectSet& simulated,
                         const RenderSettings& settings, PathOptions options, const MaterialHooks& hooks) {
    const RenderScene prepared(scene, simulated, hooks);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    options.simulated = simulated;
    if (renderer == Renderer::kDirect) {
        DirectOptions direct;
        static_cast<TraceOptions&>(direct) = options;
        const DirectLighting shading(prepared.world, prepared.materials, prepared.lights, direct);
        return render_direct(shading, camera, settings, FilmPoints::kStratified);
    }
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    return render_paths(tracer, camera, settings);
}

}  // namespace rt
