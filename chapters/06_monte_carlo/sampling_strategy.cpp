#include "sampling_strategy.hpp"

#include <string>

#include "rt/errors.hpp"

namespace rt {

std::string_view to_string(SamplingStrategy strategy) {
    switch (strategy) {
        case SamplingStrategy::kUniform:
            return "uniform";
        case SamplingStrategy::kCosine:
            return "cosine";
        case SamplingStrategy::kBrdf:
            return "brdf";
        case SamplingStrategy::kLight:
            return "light";
        case SamplingStrategy::kMis:
            return "mis";
    }
    return "mis";
}

SamplingStrategy sampling_strategy_from_string(std::string_view name) {
    for (SamplingStrategy s : kAllStrategies) {
        if (to_string(s) == name) return s;
    }
    throw InputError("--sampling: expected uniform, cosine, brdf, light or mis, got '" + std::string(name) +
                     "'");
}

}  // namespace rt
