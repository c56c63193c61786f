// What a chapter gives the run and gets back from it: its description (ChapterInfo), what its render is
// given (RunContext) and what the render returns (ChapterRun). The executable's side, the flags and files
// around the render, is run_chapter() (app.hpp); the live view calls the same render again and again.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rt/core/effect_set.hpp"
#include "rt/core/image.hpp"
#include "rt/core/scene.hpp"
#include "rt/io/output_files.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct ChapterInfo {
    const char* executable;     // "ch01_ray_generation"
    const char* description;    // one line for --help
    const char* default_scene;  // file name in assets/scenes
    EffectSet supported;
    // The suffixes of the further PFMs its runs write beside the image (x.SUFFIX.pfm), in the order of
    // ChapterRun::extra_images; probed before the render like the image's own files.
    std::vector<std::string> extra_images = {};
    // Why its render, with the flags given, cannot be split into pieces (--samples, --resume, several MPI
    // ranks): asked once the flags are read, and a split is then refused before anything renders. Empty, or
    // no function: it can be split.
    std::function<std::string()> renders_whole_because = {};
};

// What a chapter's render is given: the scene, the settings from it and the flags, and what to simulate.
struct RunContext {
    const Scene& scene;
    RenderSettings settings;
    EffectSet simulated;
};

// What it gives back: the render, notes for the summary ("dielectric material 'glass': ..."), an exact
// image when the chapter knows one analytically, and the further images of ChapterInfo::extra_images (none,
// or one for each suffix).
struct ChapterRun {
    RenderResult result;
    std::vector<std::string> notes;
    std::optional<Image> exact;
    std::vector<ExtraImage> extra_images = {};
};

// Returns nothing when a demo mode printed its own report instead of rendering an image.
using ChapterRender = std::function<std::optional<ChapterRun>(const RunContext&)>;

}  // namespace rt
