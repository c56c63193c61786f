// --live: the run as a page for a class. Instead of rendering once and writing files, the executable serves
// http://127.0.0.1:PORT (live_server.hpp) and renders again and again: the page shows the image after every
// pass of the render loop (its observer, render_observer.hpp), the summary's counters (rays by kind, samples/s,
// samples per pixel so far, the error against --reference), and the chapter's knobs (live_knobs.hpp) and
// its effects, switched without restarting: a change stops the render in progress, as an interrupt would,
// and starts it again with the flags parsed again (a value the command line would refuse is refused with
// its message, and the render goes on). Ctrl-C stops the render and the server, and the run exits with 130
// (143 for SIGTERM). It writes no file.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>

#include "rt/core/image.hpp"
#include "rt/live/live_knobs.hpp"
#include "rt/live/live_server.hpp"
#include "rt/render/chapter_run.hpp"

namespace rt {

struct LiveOptions {
    bool live = false;
    int port = kDefaultLivePort;
};

void add_live_flags(CLI::App& app, LiveOptions& options);

// What a live run renders: the scene and settings of the run, the effects the scene needs, the chapter and
// its render function, its knobs, and the reference image when one was given (a PFM).
struct LiveRun {
    const ChapterInfo& chapter;
    const Scene& scene;
    RenderSettings settings;
    EffectSet needed;
    const ChapterRender& render;
    LiveKnobs& knobs;
    const std::optional<Image>& reference;
};

// Binds the port (a port that cannot be had is an InputError, before any render), then renders and serves
// until a signal; returns the exit status, 128 + the signal's number.
int run_live(const LiveRun& run, int port);

}  // namespace rt
