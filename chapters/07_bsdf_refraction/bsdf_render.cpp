#include "bsdf_render.hpp"

#include "camera.hpp"
#include "direct_render.hpp"
#include "light_set.hpp"
#include "path_tracer.hpp"
#include "world.hpp"

namespace rt {

std::string_view to_string(Renderer renderer) {
    switch (renderer) {
        case Renderer::kDirect:
            return "direct (chapter 04)";
        case Renderer::kPaths:
            return "paths (chapter 06)";
        case Renderer::kGlass:
            return "glass (chapter 07)";
    }
    return "?";
}

Renderer choose_renderer(const EffectSet& simulated) {
    if (simulated.contains(Effect::kRefraction)) return Renderer::kGlass;
    if (simulated.without(kDirectRendererEffects).empty()) return Renderer::kDirect;
    return Renderer::kPaths;
}

BsdfPathOptions path_options_for(const EffectSet& simulated, BsdfPathOptions options) {
    options.direct = simulated.contains(Effect::kDirect);
    options.shadows = simulated.contains(Effect::kShadows);
    options.indirect = simulated.contains(Effect::kIndirect);
    options.glossy = simulated.contains(Effect::kGlossy);
    return options;
}

RenderResult render_with(Renderer renderer, const Scene& scene, const EffectSet& simulated,
                         const RenderSettings& settings, const BsdfPathOptions& options) {
    const World world(scene);
    const LightSet lights = collect_lights(scene);
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    const BsdfPathOptions o = path_options_for(simulated, options);
    switch (renderer) {
        case Renderer::kDirect: {
            const DirectLighting shading(world, scene, lights, direct_options(o));
            return render_direct(shading, camera, settings, FilmPoints::kStratified);
        }
        case Renderer::kPaths: {
            PathOptions p;
            p.termination = o.termination;
            p.direct = o.direct;
            p.shadows = o.shadows;
            p.indirect = o.indirect;
            p.glossy = o.glossy;
            p.offset = o.offset;
            const PathTracer tracer(world, scene, lights, p);
            return render_paths(tracer, camera, settings);
        }
        case Renderer::kGlass:
            break;
    }
    const BsdfPathTracer tracer(world, scene, lights, o);
    return render_bsdf_paths(tracer, camera, settings);
}

}  // namespace rt
