#include "quad_lights_flag.hpp"

#include "rt/flags/enum_flag.hpp"

namespace rt {

CLI::Option* add_quad_lights_flag(CLI::App& app, QuadLightSampling& strategy) {
    return add_enum_option(app, strategy,
                           "How quad lights are sampled: area (uniform points) or solid-angle (uniform "
                           "directions in the spherical rectangle; area where it does not apply)");
}

}  // namespace rt
