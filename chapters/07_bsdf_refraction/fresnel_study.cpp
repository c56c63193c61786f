#include "fresnel_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "fresnel.hpp"
#include "rt/io/effects.hpp"
#include "rt/core/errors.hpp"

namespace rt {
namespace {

std::vector<Real> cosines(int angles) {
    std::vector<Real> c;
    for (int i = 0; i < angles; ++i) {
        c.push_back(std::cos(radians(Real(90) * Real(i) / Real(angles - 1))));
    }
    return c;
}

// Nanoseconds per evaluation of `fresnel` over `cos_i`: the median of `repeats` sweeps. The sum of the
// results is kept (and returned through `sink`) so the compiler cannot drop the calls.
template <typename F>
double time_per_evaluation(const std::vector<Real>& cos_i, Real eta, int repeats, F fresnel, double& sink) {
    std::vector<double> ns;
    for (int r = 0; r < repeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        Real sum = 0;
        for (Real c : cos_i) sum += fresnel(c, eta);
        const auto end = std::chrono::steady_clock::now();
        sink += double(sum);
        ns.push_back(std::chrono::duration<double, std::nano>(end - start).count() / double(cos_i.size()));
    }
    std::sort(ns.begin(), ns.end());
    return ns[ns.size() / 2];
}

}  // namespace

std::vector<FresnelStudyRow> fresnel_study(Real ior, int angles, int repeats) {
    const std::vector<Real> cos_i = cosines(angles);
    std::vector<FresnelStudyRow> rows;
    double sink = 0;
    for (Real eta : {ior, 1 / ior}) {
        FresnelStudyRow row{eta, 0, 0, 0, 0, 0};
        for (std::size_t i = 0; i < cos_i.size(); ++i) {
            const double e =
                std::abs(double(fresnel_schlick(cos_i[i], eta) - fresnel_dielectric(cos_i[i], eta)));
            row.mean_error += e / double(cos_i.size());
            if (e > row.max_error) {
                row.max_error = e;
                row.max_error_angle = 90.0 * double(i) / double(angles - 1);
            }
        }
        row.exact_ns = time_per_evaluation(cos_i, eta, repeats, fresnel_dielectric, sink);
        row.schlick_ns = time_per_evaluation(cos_i, eta, repeats, fresnel_schlick, sink);
        rows.push_back(row);
    }
    if (std::isnan(sink)) throw std::runtime_error("fresnel study: NaN reflectance");
    return rows;
}

void write_fresnel_csv(Real ior, int angles, const std::filesystem::path& csv) {
    std::ofstream out(csv);
    if (!out) throw InputError("--csv: cannot write " + csv.string());
    out << "theta_deg,exact_entering,schlick_entering,exact_leaving,schlick_leaving\n";
    const std::vector<Real> cos_i = cosines(angles);
    for (std::size_t i = 0; i < cos_i.size(); ++i) {
        out << 90.0 * double(i) / double(angles - 1) << ',' << fresnel_dielectric(cos_i[i], ior) << ','
            << fresnel_schlick(cos_i[i], ior) << ',' << fresnel_dielectric(cos_i[i], 1 / ior) << ','
            << fresnel_schlick(cos_i[i], 1 / ior) << '\n';
    }
    if (!out) throw InputError("--csv: cannot write " + csv.string());
}

namespace {

// The index of the scene's first dielectric (1.5 without one).
Real scene_ior(const Scene& scene) {
    for (const Material& m : scene.materials)
        if (effect_of(m) == Effect::kRefraction) return m.ior;
    return Real(1.5);
}

}  // namespace

void run_fresnel_study(const Scene& scene, const std::string& csv) {
    const Real ior = scene_ior(scene);
    const int angles = 100001;
    const auto rows = fresnel_study(ior, angles, 15);
    std::printf(
        "Schlick against the exact Fresnel reflectance, %d angles in [0, 90] degrees; time: median of 15 "
        "sweeps\n",
        angles);
    std::printf("%-8s %-10s %12s %12s %14s %12s %12s\n", "eta", "side", "max error", "mean error",
                "at theta (deg)", "exact ns", "schlick ns");
    for (const FresnelStudyRow& r : rows) {
        std::printf("%-8.4f %-10s %12.4e %12.4e %14.3f %12.2f %12.2f\n", double(r.eta),
                    r.eta >= 1 ? "entering" : "leaving", r.max_error, r.mean_error, r.max_error_angle,
                    r.exact_ns, r.schlick_ns);
    }
    if (!csv.empty()) {
        write_fresnel_csv(ior, 91, csv);
        std::printf("wrote %s\n", csv.c_str());
    }
}

}  // namespace rt
