#include "guiding_flags.hpp"

#include <vector>

#include "rt/flags/enum_flag.hpp"
#include "rt/flags/only_with.hpp"

namespace rt {

void add_guiding_flags(CLI::App& app, GuidedRenderOptions& guided, GuidePictureRequest& picture) {
    app.add_option("--training-passes", guided.training_passes,
                   "Training passes of 1, 2, 4, ... spp before the image (0: no guiding)")
        ->check(CLI::Range(0, 16));
    add_enum_option(
        app, guided.combination,
        "The image: the last render alone (last), or every pass's image weighted by the inverse of "
        "its variance (variance)");
    app.add_option("--guided-fraction", guided.field.guided_fraction,
                   "alpha: the chance a guided vertex draws from the guide rather than the BSDF")
        ->check(CLI::Range(0.0, 0.99));
    app.add_option("--spatial-threshold", guided.field.spatial_threshold,
                   "c: a leaf of the spatial tree splits after pass k past c sqrt(2^k) vertices")
        ->check(CLI::Range(1.0, 1e9));
    app.add_option("--energy-threshold", guided.field.energy_threshold,
                   "rho: a quadrant splits past this share of its quadtree's energy")
        ->check(CLI::Range(1e-4, 0.5));
    add_enum_option(
        app, guided.field.spatial_filter,
        "Where a record lands: its vertex's leaf (nearest), or the leaf of a point drawn from a box "
        "of that leaf's size about it (box, Mueller's stochastic box filter)");
    CLI::Option* picture_flag = app.add_option(
        "--guide-picture", picture.file,
        "Write a PNG of the guide learned at --guide-at (left) beside the scattered light arriving there "
        "(right), over the equal-area square");
    app.add_option_function<std::vector<double>>(
           "--guide-at", [&](const std::vector<double>& p) { picture.at = Vec3(Vec3d(p[0], p[1], p[2])); },
           "With --guide-picture: the point, x y z (default 0 0 0)")
        ->expected(3)
        ->check(only_with({{picture_flag}}));
}

}  // namespace rt
