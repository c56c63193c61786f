#include "rt/run/split_render.hpp"

#include "rt/core/errors.hpp"

namespace rt {

void add_split_flags(CLI::App& app, SplitOptions& options) {
    app.add_option("--samples", options.samples,
                   "A:B: take only samples A … B-1 of each pixel of the --spp render, and write its film "
                   "beside the image (rt_merge adds the pieces)");
    app.add_option("--resume", options.resume, "Continue the render of this film (an interrupted one's)");
}

SplitPlan plan_split(const SplitOptions& options, const FilmIdentity& identity, const MpiSession& mpi,
                     RenderSettings& settings) {
    SplitPlan plan;
    plan.identity = identity;
    plan.whole = {0, settings.samples_per_pixel};
    if (!options.samples.empty()) {
        try {
            plan.whole = parse_sample_range(options.samples, settings.samples_per_pixel);
        } catch (const InputError& e) {
            throw InputError(std::string("--samples: ") + e.what());
        }
    }
    if (!options.resume.empty()) {
        if (mpi.size() > 1) {
            throw InputError("--resume: continues one process's film; under mpirun with " +
                             std::to_string(mpi.size()) +
                             " processes, render the samples left as --samples "
                             "pieces and merge them with rt_merge");
        }
        Film film;
        try {
            film = read_film(options.resume);
        } catch (const InputError& e) {
            throw InputError(std::string("--resume: ") + e.what());
        }
        const std::string difference = first_difference(identity, film.identity);
        if (!difference.empty()) {
            throw InputError("--resume: " + options.resume + ": a film of another render: " + difference);
        }
        // --samples may extend the film's range (0:64 continued to 0:128), not move or shrink it.
        if (options.samples.empty()) {
            plan.whole = film.range;
        } else if (plan.whole.first != film.range.first || plan.whole.end < film.range.end) {
            throw InputError("--resume: " + options.resume + ": takes samples " + to_string(film.range) +
                             ": --samples can only extend it (" + std::to_string(film.range.first) +
                             ":B, B >= " + std::to_string(film.range.end) + "), got " +
                             to_string(plan.whole));
        }
        film.range = plan.whole;
        plan.resumed = std::make_shared<const Film>(std::move(film));
        settings.resume = &plan.resumed->sums;
    }
    plan.writes_film = !options.samples.empty() || !options.resume.empty();
    // A whole render in one process leaves the range unset, so a study that renders the scene again at
    // another spp (chapter 04's shadow study, chapter 07's depth study) takes all of its own samples.
    if (plan.writes_film || mpi.size() > 1)
        settings.samples = split_range(plan.whole, mpi.size(), mpi.rank());
    return plan;
}

std::optional<Film> film_of(const SplitPlan& plan, const RenderResult& result, const MpiSession& mpi) {
    if (!plan.writes_film && !result.interrupted) return std::nullopt;
    if (result.sums.empty()) {
        if (!plan.writes_film) return std::nullopt;  // an interrupted splatting render: its image only
        throw std::runtime_error("this render did not sample pixels through the render loop: it has no film");
    }
    // The ranks' interrupted pieces are not one range: their sum cannot be continued.
    if (mpi.size() > 1 && result.interrupted) return std::nullopt;
    return Film{plan.identity, plan.whole, result.sums};
}

}  // namespace rt
