#include "sample_stream.hpp"

#include <string>

#include "rt/errors.hpp"

namespace rt {

std::string_view to_string(PointSet points) {
    switch (points) {
        case PointSet::kIndependent:
            return "independent";
        case PointSet::kStratified:
            return "stratified";
        case PointSet::kSobol:
            return "sobol";
    }
    return "?";
}

PointSet point_set_from_string(std::string_view name) {
    for (PointSet p : kAllPointSets) {
        if (to_string(p) == name) return p;
    }
    throw InputError("--sampler: unknown sampler \"" + std::string(name) +
                     "\"; expected independent, stratified or sobol");
}

}  // namespace rt
