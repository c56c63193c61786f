// What a chapter executable does around its render: the core flags of common/README.md, loading and checking
// the scene, the output files, the summary, and exit statuses (0 done, 2 bad usage or input, 1 failure,
// 128 + a signal's number when one ended the run: 130 for SIGINT, 143 for SIGTERM; interrupt.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rt/effect_set.hpp"
#include "rt/image.hpp"
#include "rt/only_with.hpp"
#include "rt/output_files.hpp"
#include "rt/render_loop.hpp"
#include "rt/scene.hpp"
#include "rt/strict_flags.hpp"

namespace rt {

// A text flag given empty is refused (strict_flags.hpp): empty here means not given.
struct CoreOptions {
    std::string scene;  // empty: the chapter's default scene
    std::string out;    // empty: <executable>.png in the current folder
    std::optional<int> width, height, spp;
    std::uint64_t seed = 1;
    int threads = 0;
    std::string reference;
    std::string heat;  // --heat FILE.png: the per-pixel heat maps (heat_maps.hpp); empty: none
    bool quiet = false;
};

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

using ChapterFlags = std::function<void(CLI::App&)>;
// Returns nothing when a demo mode printed its own report instead of rendering an image.
using ChapterRender = std::function<std::optional<ChapterRun>(const RunContext&)>;

int run_chapter(int argc, char** argv, const ChapterInfo& chapter, const ChapterFlags& add_flags,
                const ChapterRender& render);

}  // namespace rt
