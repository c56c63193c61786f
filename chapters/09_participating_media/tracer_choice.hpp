// Chapter 09 is the course's most complete renderer, so it chooses, scene by scene, the strategy that pays:
//   combined (chapter 08): a scene whose mirrors or smooth glass are lit by area or point lights; light paths
//            find the caustics the camera sees, chapter 06's paths the rest (lesson § 10);
//   paths:   every other scene; through fog (a medium between the shapes that scatters), with Cycles'
//            volume sampling where the flags leave it open: equiangular points by MIS (§ 7) and quad lights
//            by solid angle (chapter 04), whose density has no 1 / d² to blow up at a point beside the lamp.
// The combined tracer is chosen only where it simulates what the paths would: no medium, no environment, no
// shading normals, a pinhole camera; it renders whole, so such a scene is split into pieces only with
// `--tracer paths`. The summary says which was chosen and why.
#pragma once

#include <optional>
#include <string>

#include "rt/core/enum_names.hpp"
#include "rt/render/chapter_run.hpp"
#include "volume_path_tracer.hpp"

namespace rt {

enum class TracerRule { kAuto, kPaths };

constexpr auto names_of(TracerRule) {
    return enum_names<TracerRule>("--tracer", {{TracerRule::kAuto, "auto"}, {TracerRule::kPaths, "paths"}});
}

// The flags the command line gave, which the choice keeps.
struct GivenFlags {
    bool distance_sampling = false;
    bool quad_lights = false;
    bool termination = false;  // a rule or a depth other than the loop's own (flags or the scene's max_depth)
};

struct TracerChoice {
    bool combined = false;
    std::optional<DistanceSampling> distance;      // set: chosen for the fog
    std::optional<QuadLightSampling> quad_lights;  // set: chosen for the fog
    std::string because;                           // the summary's reason
};

// Throws InputError for a piece of a split render of a scene that the combined tracer would render.
TracerChoice choose_tracer(TracerRule rule, const RunContext& context, GivenFlags given = {});

// Renders the run by the chosen tracer, simulating what the run does, with the notes its summary prints (the
// choice's line first).
ChapterRun render_by_choice(TracerRule rule, const RunContext& context, PathOptions options, MediumWalk walk,
                            GivenFlags given = {});

}  // namespace rt
