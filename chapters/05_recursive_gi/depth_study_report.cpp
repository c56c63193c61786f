#include "depth_study_report.hpp"

#include <optional>

#include "02_intersection/world.hpp"
#include "gi_render.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/scene_loader.hpp"

namespace rt {

void run_depth_study(const Scene& given, const CLI::App& cli, RenderSettings settings,
                     const EffectSet& simulated, const TerminationFlags& termination,
                     const DepthStudyRequest& request) {
    if (!request.csv.empty()) check_writable("--csv", request.csv);
    std::optional<Scene> loaded;
    {
        const World probe(given);
        if (!find_furnace(given, probe)) loaded = load_scene(scene_path("ch05_furnace.json"));
    }
    const Scene& scene = loaded ? *loaded : given;
    // The furnace file's own image size and samples, unless the flags set them.
    if (loaded && cli.count("--width") == 0) settings.width = loaded->image.width;
    if (loaded && cli.count("--height") == 0) settings.height = loaded->image.height;
    if (loaded && cli.count("--spp") == 0) settings.samples_per_pixel = loaded->image.spp;
    const World world(scene);
    const auto furnace = find_furnace(scene, world);
    if (!furnace) throw InputError(scene.file + ": --depth-study: not a furnace (a closed emissive box)");
    const Real min_throughput = termination.settings.min_throughput;
    const int roulette_start = termination.settings.roulette_start_depth;
    std::vector<TerminationSettings> rules;
    for (int d : request.depths) rules.push_back({Termination::kMaxDepth, d, min_throughput, roulette_start});
    const int cap = termination.max_depth.value_or(kSafetyDepthCap);
    rules.push_back({Termination::kRussianRoulette, cap, min_throughput, roulette_start});
    for (Real t : request.throughputs) rules.push_back({Termination::kMinThroughput, cap, t, roulette_start});
    const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
    DirectOptions direct;
    direct.simulated = simulated;
    std::vector<DepthStudyRow> rows = depth_study(world, scene, *furnace, camera, settings, rules, direct);
    DirectOptions no_light_sampling = direct;
    no_light_sampling.simulated = direct.simulated.without({Effect::kDirect});
    for (const DepthStudyRow& r :
         depth_study(world, scene, *furnace, camera, settings, rules, no_light_sampling))
        rows.push_back(r);
    print_depth_study(rows, scene, *furnace, settings, request.csv);
}

}  // namespace rt
