// A render split by sample range, as the chapter executables run it: the flags --samples A:B and --resume
// FILM.film, the range this process takes (its MPI rank's share), and the film the run leaves beside its
// image. The mechanism is the render loop's (settings.samples, settings.resume) and the film's (film.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

#include "rt/io/film.hpp"
#include "rt/render/render_loop.hpp"
#include "rt/run/mpi_split.hpp"

namespace rt {

struct SplitOptions {
    std::string samples;  // "A:B", empty: all
    std::string resume;   // a film to continue (to the end of --samples, when given), empty: none
};
void add_split_flags(CLI::App& app, SplitOptions& options);

struct SplitPlan {
    FilmIdentity identity;                // of this run
    SampleRange whole;                    // the samples of this run, all ranks together
    std::shared_ptr<const Film> resumed;  // the film --resume continues (settings.resume points into it)
    bool writes_film = false;             // --samples or --resume: the run's film goes beside its image
};

// Checks the flags against the run (`identity`) and sets settings.samples (this rank's share of the range)
// and settings.resume. Throws InputError naming the flag: a bad range, a film of another render, --resume
// with more than one rank.
SplitPlan plan_split(const SplitOptions& options, const FilmIdentity& identity, const MpiSession& mpi,
                     RenderSettings& settings);

// After the render (and MPI's gather): the film the run leaves, when it leaves one: asked for (--samples,
// --resume) or interrupted (to resume), on rank 0 of a job of one. Throws std::runtime_error when one is
// needed and the render did not sample pixels through the render loop.
std::optional<Film> film_of(const SplitPlan& plan, const RenderResult& result, const MpiSession& mpi);

}  // namespace rt
