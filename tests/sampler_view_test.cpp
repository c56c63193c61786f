// The sampler view's answers (chapters/09_participating_media/sampler_view/sampler_report.hpp), without the
// server: a right sampler gets the harness's own statistic and passes; the registry's mistake, a sampler
// whose pdf lacks its Jacobian, fails, with the cells where it does; bad queries are refused with 400 and one
// line; a sampler that throws (the student edition's unwritten exercise) is answered 500 with its message.
// The page itself is tested in a browser by tests/cli/sampler_view_browser.py.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "sampler_report.hpp"

using namespace rt;
using namespace rt::test;
using nlohmann::json;

namespace {

// The registered sampler named `name`.
const RegisteredSampler& registered(const std::vector<RegisteredSampler>& registry, const std::string& name) {
    for (const RegisteredSampler& s : registry)
        if (s.name == name) return s;
    FAIL(name << " is not in the registry");
    throw std::logic_error("unreachable");
}

json answer_json(const LiveAnswer& a) {
    INFO(a.body.substr(0, 300));
    REQUIRE(a.status == 200);
    REQUIRE(a.content_type == "application/json");
    return json::parse(a.body);
}

}  // namespace

TEST_CASE("The sampler view's verdict on a right sampler is the harness's: the same statistic, and it passes",
          "[sampler_view][ex:ch07.fresnel_conductor][statistical]") {
    const std::vector<RegisteredSampler> registry = sampler_registry();
    const json a = answer_json(sample_answer(
        registry,
        {{"name", "rough_conductor"}, {"roughness", "0.3"}, {"incident_angle", "70"}, {"seed", "3104"}}));
    // The harness on the same warp (roughness 0.3, wo at 70 degrees, seed 3104: chapter 07's test).
    const Warp warp = registered(registry, "rough_conductor").make({0.3, 70}, 3104);
    const ChiSquare r = test_directions(warp.sample, warp.pdf, 3104);
    require_fit_with_losses(r, kSamplerViewLevel);
    CHECK(a["samples"] == kDirectionSamples);
    CHECK(a["statistic"].get<double>() == r.statistic);
    CHECK(a["dof"] == r.dof);
    CHECK(a["p_value"].get<double>() == r.p_value);
    CHECK(a["lost"] == r.lost);
    CHECK(a["level"] == kSamplerViewLevel);
    CHECK(a["problems"].empty());
    CHECK(a["failing_cells"].empty());
    CHECK(a["observed"].size() == std::size_t(48 * 96));
    CHECK(a["expected"].size() == std::size_t(48 * 96));
}

TEST_CASE(
    "The sampler view fails a sampler whose pdf lacks its Jacobian, as the harness does, and shows where",
    "[sampler_view][statistical]") {
    const std::vector<RegisteredSampler> registry = sampler_registry();
    const json a =
        answer_json(sample_answer(registry, {{"name", "mistake_missing_jacobian"}, {"seed", "5"}}));
    const Warp warp = registered(registry, "mistake_missing_jacobian").make({}, 5);
    const ChiSquare r = test_directions(warp.sample, warp.pdf, 5);
    CHECK(a["statistic"].get<double>() == r.statistic);
    CHECK(r.p_value < 1e-12);
    CHECK(a["p_value"].get<double>() == r.p_value);
    const std::vector<std::string> problems = a["problems"];
    CHECK(problems == fit_problems(r, kSamplerViewLevel, false));
    REQUIRE(problems.size() == 2);  // ∫ pdf = 2 / π, and p
    CHECK(problems[0].find("integrates to 0.63") != std::string::npos);
    CHECK(problems[1].find("the histogram differs from the density") != std::string::npos);
    // The samples crowd the pole, where sin θ is small: the top row of cells is among the failing ones.
    const std::vector<int> failing = a["failing_cells"];
    const int top_row = 47 * 96;
    CHECK(failing.size() > 96);
    CHECK(std::count_if(failing.begin(), failing.end(), [&](int c) { return c >= top_row; }) == 96);
}

TEST_CASE("The sampler view refuses bad queries with 400 and one line that says what is wrong",
          "[sampler_view]") {
    const std::vector<RegisteredSampler> registry = sampler_registry();
    const std::vector<std::pair<LiveQuery, std::string>> cases = {
        {{}, "/sample: name: which sampler? one of uniform_hemisphere, cosine_hemisphere"},
        {{{"name", "power_cosin"}},
         "/sample: name: unknown sampler \"power_cosin\" (did you mean power_cosine?)"},
        {{{"name", "power_cosine"}, {"exponent", "500"}},
         "/sample: power_cosine: exponent: must be in [0, 200], got 500"},
        {{{"name", "power_cosine"}, {"exponent", "six"}},
         "/sample: power_cosine: exponent: must be a number, got \"six\""},
        {{{"name", "henyey_greenstein"}, {"g", " 0.5"}},
         "/sample: henyey_greenstein: g: must be a number, got \" 0.5\""},
        {{{"name", "henyey_greenstein"}, {"g", "0x0.8p0"}},
         "/sample: henyey_greenstein: g: must be a number, got \"0x0.8p0\""},
        {{{"name", "henyey_greenstein"}, {"g", "nan"}},
         "/sample: henyey_greenstein: g: must be a number, got \"nan\""},
        {{{"name", "henyey_greenstein"}, {"g", "1"}},
         "/sample: henyey_greenstein: g: must be in [-0.95, 0.95], got 1"},
        {{{"name", "uniform_sphere"}, {"roughness", "1"}},
         "/sample: uniform_sphere: no parameter \"roughness\""},
        {{{"name", "uniform_sphere"}, {"samples", "10"}},
         "/sample: samples: must be in [1000, 1000000], got 10"},
        {{{"name", "uniform_sphere"}, {"samples", "1e5"}}, "/sample: samples: must be a whole number"},
        {{{"name", "uniform_sphere"}, {"seed", "-1"}}, "/sample: seed: must be a whole number"},
    };
    for (const auto& [query, message] : cases) {
        const LiveAnswer a = sample_answer(registry, query);
        INFO(a.body);
        CHECK(a.status == 400);
        CHECK(a.body.starts_with(message));
        CHECK(a.body.find('\n') == a.body.size() - 1);
    }
}

TEST_CASE("The sampler view answers a sampler that throws (an unwritten exercise) with 500 and its message",
          "[sampler_view]") {
    const RegisteredSampler stub{
        "stub",
        "04",
        "an exercise not written yet",
        {},
        [](const std::vector<double>&, std::uint64_t) -> Warp {
            throw std::logic_error("not implemented: ch04.power_cosine — see the lesson");
        }};
    const LiveAnswer a = sample_answer({stub}, {{"name", "stub"}});
    CHECK(a.status == 500);
    CHECK(a.body == "stub: the sampler failed: not implemented: ch04.power_cosine — see the lesson\n");
}

TEST_CASE(
    "The sampler view lists every sampler of chapters 04, 06, 07 and 09, and chapter 01's mistake, with its "
    "parameters",
    "[sampler_view]") {
    const json list = answer_json(samplers_answer(sampler_registry()))["samplers"];
    std::set<std::string> chapters, names;
    for (const json& s : list) {
        chapters.insert(s["chapter"].get<std::string>());
        names.insert(s["name"].get<std::string>());
        for (const json& p : s["parameters"]) {
            CHECK(p["min"].get<double>() <= p["value"].get<double>());
            CHECK(p["value"].get<double>() <= p["max"].get<double>());
        }
    }
    CHECK(chapters == std::set<std::string>{"01", "04", "06", "07", "09"});
    CHECK(names.size() == list.size());
    CHECK(names.count("henyey_greenstein") == 1);
    CHECK(names.count("rough_dielectric") == 1);
}

TEST_CASE(
    "The sampler view fits equiangular distances in 200 cells of the segment: the light over it, past its "
    "end, behind",
    "[sampler_view][statistical][equiangular]") {
    // Chapter 09's chi-square cases: (Δ, D) = (3, 0.5), (15, 2), (−4, 1), on a segment of length 10, with its
    // seed, 7 (the same draws).
    const std::vector<RegisteredSampler> registry = sampler_registry();
    for (const auto& [delta, distance] :
         std::vector<std::pair<std::string, std::string>>{{"3", "0.5"}, {"15", "2"}, {"-4", "1"}}) {
        const json a = answer_json(sample_answer(
            registry, {{"name", "equiangular"}, {"delta", delta}, {"distance", distance}, {"seed", "7"}}));
        INFO("delta " << delta << ", D " << distance << ": p = " << a["p_value"] << ", " << a["problems"]);
        CHECK(a["domain"] == "segment");
        CHECK(a["t_max"] == 10.0);
        CHECK(a["observed"].size() == 200);
        CHECK(a["problems"].empty());
        CHECK(std::abs(a["integral"].get<double>() - 1) < 1e-3);
    }
}
