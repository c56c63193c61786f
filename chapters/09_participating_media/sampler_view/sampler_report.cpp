#include "sampler_report.hpp"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "rt/core/did_you_mean.hpp"
#include "rt/core/printable.hpp"
#include "rt/core/whole_number.hpp"

namespace rt::test {

namespace {

using nlohmann::json;

// A refusal: HTTP 400 and one line.
struct BadQuery {
    std::string message;
};

LiveAnswer refused(int status, const std::string& message) {
    return {status, message + "\n", "text/plain; charset=utf-8"};
}

const RegisteredSampler& find_sampler(const std::vector<RegisteredSampler>& registry,
                                      const LiveQuery& query) {
    const auto given = query.find("name");
    std::vector<std::string_view> names;
    std::string listed;
    for (const RegisteredSampler& s : registry) {
        if (given != query.end() && s.name == given->second) return s;
        names.push_back(s.name);
        listed += (listed.empty() ? "" : ", ") + s.name;
    }
    if (given == query.end()) throw BadQuery{"name: which sampler? one of " + listed};
    const auto near = closest_match(given->second, names);
    throw BadQuery{"name: unknown sampler " + shown_value(given->second) +
                   (near ? " (did you mean " + *near + "?)" : "") + "; the samplers: " + listed};
}

// A bound as a reader writes it: 200, 0.95.
std::string shown_number(double x) {
    return x == std::floor(x) && std::abs(x) < 1e15 ? std::to_string(static_cast<long long>(x))
                                                    : json(x).dump();
}

// A decimal number within [min, max], all of `text` (no space, no hexadecimal, no "inf").
double number_in(const std::string& where, const std::string& text, double min, double max) {
    const bool decimal = !text.empty() && text.find_first_not_of("0123456789.+-eE") == std::string::npos;
    char* end = nullptr;
    const double value = decimal ? std::strtod(text.c_str(), &end) : 0;
    if (!decimal || end != text.c_str() + text.size() || !std::isfinite(value))
        throw BadQuery{where + ": must be a number, got " + shown_value(text)};
    if (!(value >= min && value <= max))
        throw BadQuery{where + ": must be in [" + shown_number(min) + ", " + shown_number(max) + "], got " +
                       text};
    return value;
}

// A whole number within [min, max], or `otherwise` when the query does not give it.
long long whole_in(const LiveQuery& query, const std::string& name, long long min, long long max,
                   long long otherwise) {
    const auto given = query.find(name);
    if (given == query.end()) return otherwise;
    const std::string problem = whole_number_error(given->second, false);
    if (!problem.empty()) throw BadQuery{name + ": " + problem};
    const double value = number_in(name, given->second, double(min), double(max));
    return static_cast<long long>(value);
}

// The values of the sampler's parameters (its defaults where the query gives none); any other name is
// refused.
std::vector<double> parameter_values(const RegisteredSampler& sampler, const LiveQuery& query) {
    std::vector<double> values;
    for (const SamplerParameter& p : sampler.parameters) {
        const auto given = query.find(p.name);
        values.push_back(given == query.end()
                             ? p.value
                             : number_in(sampler.name + ": " + p.name, given->second, p.min, p.max));
    }
    for (const auto& [name, value] : query) {
        bool known = name == "name" || name == "samples" || name == "seed";
        for (const SamplerParameter& p : sampler.parameters) known = known || p.name == name;
        if (known) continue;
        std::string parameters;
        for (const SamplerParameter& p : sampler.parameters) parameters += " " + p.name;
        throw BadQuery{sampler.name + ": no parameter " + shown_value(name) +
                       " (it takes:" + (parameters.empty() ? " none" : parameters) + "; and samples, seed)"};
    }
    return values;
}

// The answer's histogram, density and verdict, whatever the domain.
json verdict(const RegisteredSampler& sampler, const std::vector<double>& observed,
             const std::vector<double>& expected, ChiSquare r) {
    json rounded = json::array();
    for (double e : expected) rounded.push_back(std::round(e * 1000) / 1000);
    return {{"name", sampler.name},
            {"observed", observed},
            {"expected", rounded},
            {"statistic", r.statistic},
            {"dof", r.dof},
            {"p_value", r.p_value},
            {"level", kSamplerViewLevel},
            {"integral", r.expected_total / r.samples},
            {"bad_samples", r.bad_samples},
            {"lost", r.lost},
            {"problems", fit_problems(r, kSamplerViewLevel, sampler.may_lose)},
            {"failing_cells", failing_cells(observed, expected, kSamplerViewLevel)}};
}

json fitted(const RegisteredSampler& sampler, const std::vector<double>& values, int samples,
            std::uint64_t seed) {
    if (sampler.make_segment) {
        const SegmentWarp warp = sampler.make_segment(values);
        const SegmentHistogram h = histogram_segment(warp, seed, samples);
        ChiSquare r = chi_square(h.observed, h.expected);
        r.bad_samples = h.bad;
        r.samples = samples;
        json a = verdict(sampler, h.observed, h.expected, r);
        a.update({{"domain", "segment"}, {"t_max", warp.t_max}, {"nz", 1}, {"nphi", h.observed.size()}});
        return a;
    }
    const Warp warp = sampler.make(values, seed);
    const DirectionHistogram h = histogram_directions(warp.sample, warp.pdf, seed, samples);
    json a = verdict(sampler, h.observed, h.expected, test_histogram(h, samples));
    a.update({{"domain", "sphere"}, {"nz", h.grid.nz}, {"nphi", h.grid.nphi}});
    return a;
}

}  // namespace

std::vector<int> failing_cells(const std::vector<double>& observed, const std::vector<double>& expected,
                               double level) {
    int considered = 0;
    for (double e : expected) considered += e >= 5 ? 1 : 0;
    const double cell_level = sidak_level(std::max(1, considered), level);
    std::vector<int> failing;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const double o = observed[i], e = expected[i];
        if (e >= 5 && chi_square_p_value((o - e) * (o - e) / e, 1) < cell_level) failing.push_back(int(i));
    }
    return failing;
}

LiveAnswer samplers_answer(const std::vector<RegisteredSampler>& registry) {
    json list = json::array();
    for (const RegisteredSampler& s : registry) {
        json parameters = json::array();
        for (const SamplerParameter& p : s.parameters)
            parameters.push_back({{"name", p.name},
                                  {"meaning", p.meaning},
                                  {"min", p.min},
                                  {"max", p.max},
                                  {"value", p.value}});
        list.push_back(
            {{"name", s.name}, {"chapter", s.chapter}, {"title", s.title}, {"parameters", parameters}});
    }
    return {200, json{{"samplers", list},
                      {"max_samples", kDirectionSamples},
                      {"min_samples", kSamplerViewMinSamples},
                      {"level", kSamplerViewLevel}}
                     .dump()};
}

LiveAnswer sample_answer(const std::vector<RegisteredSampler>& registry, const LiveQuery& query) {
    try {
        const RegisteredSampler& sampler = find_sampler(registry, query);
        const std::vector<double> values = parameter_values(sampler, query);
        const int samples =
            int(whole_in(query, "samples", kSamplerViewMinSamples, kDirectionSamples, kDirectionSamples));
        const auto seed = std::uint64_t(whole_in(query, "seed", 0, 1LL << 32, 1));
        try {
            json answer = fitted(sampler, values, samples, seed);
            answer.update({{"samples", samples}, {"seed", seed}});
            return {200, answer.dump()};
        } catch (const std::exception& e) {  // the student edition's "not implemented: ...", or a failure
            return refused(500, sampler.name + ": the sampler failed: " + e.what());
        }
    } catch (const BadQuery& bad) {
        return refused(400, "/sample: " + bad.message);
    }
}

}  // namespace rt::test
