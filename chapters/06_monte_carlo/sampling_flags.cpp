#include "sampling_flags.hpp"

#include "04_direct_lighting/quad_lights_flag.hpp"
#include "rt/flags/enum_flag.hpp"

namespace rt {

CLI::Option* add_sampling_flag(CLI::App& app, SamplingStrategy& strategy, QuadLightSampling& quad_lights) {
    CLI::Option* sampling =
        add_enum_option(app, strategy, "How directions are drawn: " + joined_names<SamplingStrategy>());
    add_quad_lights_flag(app, quad_lights);
    return sampling;
}

CLI::Option* add_sampler_flag(CLI::App& app, PointSet& points) {
    return add_enum_option(
        app, points,
        "Where a sample's numbers come from: independent|stratified|sobol (Owen-scrambled Sobol)");
}

}  // namespace rt
