// A white furnace for rough metal (not a test): `ch07_metal_furnace` prints the table of the lesson's section
// "Rough metals". A perfect reflector (η = 0, k = 1: Fresnel's R is 1 at every angle) is made rough; its
// directional albedo E(θ_o) = ∫ f cos θ_i dω_i would be 1 if the model kept every photon, and what it lacks
// is single scattering's loss: light that would reflect a second time off a neighbouring facet (G2 < 1, and
// samples that leave below the surface). E is the mean of the sample weights f cos θ_i / pdf = F G2 / G1(wo),
// over --samples samples, each at most 1 (the standard error is printed).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>

#include "conductor.hpp"
#include "rt/core/random.hpp"
#include "rt/run/strict_flags.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    CLI::App app{"ch07_metal_furnace: the albedo of a rough perfect reflector, by roughness and angle"};
    int samples = 1000000;
    app.add_option("--samples", samples, "Samples per albedo")->check(CLI::Range(100, 100000000));
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;

    const Vec3 n{0, 0, 1};
    const double angles[] = {0, 45, 70, 85};
    std::printf(
        "albedo E(theta_o) of a rough perfect reflector (eta 0, k 1), %d samples each; loss = 1 - E\n",
        samples);
    std::printf("%-10s", "roughness");
    for (double a : angles) std::printf("  E(%2.0f deg)", a);
    std::printf("  largest std. error\n");
    for (double roughness : {0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0}) {
        const Conductor metal(Color(0), Color(1), Real(roughness));
        std::printf("%-10.2f", roughness);
        double worst = 0;
        for (double degrees : angles) {
            const double t = degrees * std::numbers::pi / 180;
            const Vec3 wo{Real(std::sin(t)), 0, Real(std::cos(t))};
            Pcg32 rng(42, 5);
            double sum = 0, sum2 = 0;
            for (int i = 0; i < samples; ++i) {
                const BsdfSample s = metal.sample(wo, n, rng.next_vec2(), 0);
                const double w = s.pdf > 0 ? double(s.f.g) * double(glm::dot(s.wi, n)) / double(s.pdf) : 0;
                sum += w;
                sum2 += w * w;
            }
            const double mean = sum / samples;
            worst = std::max(worst, std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / samples));
            std::printf("  %10.4f", mean);
        }
        std::printf("  %.1e\n", worst);
    }
    return 0;
}
