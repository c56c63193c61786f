// The flags of this chapter's termination rules, which every later chapter's paths take too: --termination
// (the rule) and --max-depth (the depth rule's N, and a hard cap for the other rules).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>

#include "rt/core/scene.hpp"
#include "termination.hpp"

namespace rt {

struct TerminationFlags {
    TerminationSettings settings;  // its rule from --termination; the rest as the chapter's flags set them
    std::optional<int> max_depth;  // --max-depth; not given: the scene's, else 8 with the depth rule, else
                                   // kSafetyDepthCap

    // The settings with the maximum depth decided for `scene`.
    TerminationSettings resolved(const Scene& scene) const;
};

// Adds --termination and --max-depth; returns the --termination option (for the checks of flags that matter
// only with one rule).
CLI::Option* add_termination_flags(CLI::App& app, TerminationFlags& flags);

}  // namespace rt
