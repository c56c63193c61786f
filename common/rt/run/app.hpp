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

#include "rt/flags/only_with.hpp"
#include "rt/render/chapter_run.hpp"
#include "rt/run/strict_flags.hpp"

namespace rt {

// A text flag given empty is refused (strict_flags.hpp): empty here means not given.
struct CoreOptions {
    std::string scene;  // empty: the chapter's default scene
    std::string out;    // empty: <executable>.png in the current folder
    bool exr_float = false;  // --exr-float: a .exr --out of floats, not half floats
    std::optional<int> width, height, spp;
    std::uint64_t seed = 1;
    int threads = 0;
    std::string reference;
    std::string heat;  // --heat FILE.png: the per-pixel heat maps (heat_maps.hpp); empty: none
    bool quiet = false;
};

using ChapterFlags = std::function<void(CLI::App&)>;

int run_chapter(int argc, char** argv, const ChapterInfo& chapter, const ChapterFlags& add_flags,
                const ChapterRender& render);

}  // namespace rt
