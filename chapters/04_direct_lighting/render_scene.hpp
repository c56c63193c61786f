// What a render from chapter 04 on builds once from the scene file's data: the World to trace (chapter 02),
// the material table for the simulated effects, and the lights to sample. Tracers hold references into it,
// so it outlives them.
#pragma once

#include "02_intersection/world.hpp"
#include "light_set.hpp"
#include "material_table.hpp"
#include "rt/core/effect_set.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct RenderScene {
    RenderScene(const Scene& scene_, const EffectSet& simulated,
                const MaterialHooks& hooks = direct_lighting_materials())
        : scene(scene_),
          world(scene_, world_options_for(simulated)),
          materials(scene_, simulated, hooks),
          lights(collect_lights(scene_)) {}

    const Scene& scene;
    World world;
    MaterialTable materials;
    LightSet lights;
};

}  // namespace rt
