#include "sampling_flags.hpp"

#include "rt/flags/enum_flag.hpp"

namespace rt {

CLI::Option* add_sampling_flag(CLI::App& app, SamplingStrategy& strategy) {
    return add_enum_option(app, strategy, "How directions are drawn: " + joined_names<SamplingStrategy>());
}

CLI::Option* add_sampler_flag(CLI::App& app, PointSet& points) {
    return add_enum_option(
        app, points,
        "Where a sample's numbers come from: independent|stratified|sobol (Owen-scrambled Sobol)");
}

}  // namespace rt
