#include "convergence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>

#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/image_io.hpp"

namespace rt {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kReferenceSeedA = 1001;
constexpr std::uint64_t kReferenceSeedB = 1002;

// mean((a − b)²) over every channel of every pixel.
double mean_squared_difference(const Image& a, const Image& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const Vec3d d = Vec3d(a.pixels()[i]) - Vec3d(b.pixels()[i]);
        sum += glm::dot(d, d);
    }
    return sum / (3.0 * double(a.pixels().size()));
}

// mean((a − ref)² / (ref² + 0.01)): the relative MSE of error_metrics.hpp.
double relative_squared_difference(const Image& a, const Image& ref) {
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double r = double(ref.pixels()[i][c]), d = double(a.pixels()[i][c]) - r;
            sum += d * d / (r * r + 0.01);
        }
    }
    return sum / (3.0 * double(a.pixels().size()));
}

RenderResult render_with(const RenderScene& prepared, PathOptions options, SamplingStrategy strategy,
                         const PinholeCamera& camera, const RenderSettings& settings) {
    options.strategy = strategy;
    const PathTracer tracer(prepared.world, prepared.materials, prepared.lights, options);
    return render_paths(tracer, camera, settings);
}

}  // namespace

fs::path reference_path(const fs::path& folder, const Scene& scene, int width, int height, int spp) {
    const std::string stem = fs::path(scene.file).stem().string();
    return folder / ("ch06_reference_" + stem + "_" + std::to_string(width) + "x" + std::to_string(height) +
                     "_" + std::to_string(spp) + "spp.pfm");
}

Reference converged_reference(const RenderScene& prepared, const PathOptions& options,
                              const PinholeCamera& camera, RenderSettings settings, int spp,
                              const fs::path& folder) {
    Reference ref;
    ref.spp = spp;
    ref.file = reference_path(folder, prepared.scene, settings.width, settings.height, spp);
    fs::path half = ref.file;
    half.replace_filename(ref.file.stem().string() + "_half.pfm");
    std::error_code ec;
    if (fs::exists(ref.file, ec) && fs::exists(half, ec)) {
        Image mean = read_pfm(ref.file), a = read_pfm(half);
        if (mean.width() == settings.width && mean.height() == settings.height && a.width() == mean.width() &&
            a.height() == mean.height()) {
            // A − (A + B)/2 = (A − B)/2, so mean((A − ref)²) = mean((A − B)²) / 4.
            ref.noise_mse = mean_squared_difference(a, mean);
            ref.noise_relative_mse = relative_squared_difference(a, mean);
            ref.image = std::move(mean);
            ref.cached = true;
            return ref;
        }
    }
    for (const fs::path& file : {half, ref.file}) check_writable("--cache", file);  // before rendering
    settings.samples_per_pixel = std::max(1, spp / 2);
    settings.seed = kReferenceSeedA;
    const RenderResult a = render_with(prepared, options, SamplingStrategy::kMis, camera, settings);
    settings.seed = kReferenceSeedB;
    const RenderResult b = render_with(prepared, options, SamplingStrategy::kMis, camera, settings);
    if (a.interrupted || b.interrupted) throw std::runtime_error("the reference render was interrupted");
    Image mean(settings.width, settings.height);
    for (std::size_t i = 0; i < mean.pixels().size(); ++i) {
        mean.pixels()[i] = (a.image.pixels()[i] + b.image.pixels()[i]) * Real(0.5);
    }
    ref.noise_mse = mean_squared_difference(a.image, mean);
    ref.noise_relative_mse = relative_squared_difference(a.image, mean);
    ref.seconds = a.seconds + b.seconds;
    write_pfm(a.image, half);
    write_pfm(mean, ref.file);
    ref.image = std::move(mean);
    return ref;
}

std::vector<ConvergenceRow> convergence_study(const RenderScene& prepared, PathOptions options,
                                              const PinholeCamera& camera, RenderSettings settings,
                                              const Reference& reference,
                                              const std::vector<SamplingStrategy>& strategies, int max_spp) {
    std::vector<ConvergenceRow> rows;
    for (SamplingStrategy strategy : strategies) {
        for (int spp = 1; spp <= max_spp; spp *= 2) {
            settings.samples_per_pixel = spp;
            const std::clock_t cpu_start = std::clock();
            const RenderResult r = render_with(prepared, options, strategy, camera, settings);
            const double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
            if (r.interrupted) return rows;
            const ErrorMetrics e = compare(r.image, reference.image);
            rows.push_back({strategy, spp, e.rmse, e.rmse * e.rmse - reference.noise_mse, r.seconds, cpu,
                            e.relative_mse - reference.noise_relative_mse});
        }
    }
    return rows;
}

std::vector<EfficiencyRow> efficiency_table(const std::vector<ConvergenceRow>& rows) {
    std::vector<EfficiencyRow> table;
    for (SamplingStrategy s : kAllStrategies) {
        std::vector<const ConvergenceRow*> mine;
        for (const ConvergenceRow& r : rows)
            if (r.strategy == s) mine.push_back(&r);
        if (mine.empty()) continue;
        // Least squares of y = log RMSE on x = log spp.
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (const ConvergenceRow* r : mine) {
            const double x = std::log(double(r->spp)), y = std::log(r->rmse);
            sx += x, sy += y, sxx += x * x, sxy += x * y;
        }
        const double n = double(mine.size());
        const double denominator = n * sxx - sx * sx;
        const double slope = denominator > 0 ? (n * sxy - sx * sy) / denominator : 0.0;
        const ConvergenceRow& last = *mine.back();
        const double cpu = std::max(last.cpu_seconds, 1e-9);
        // An MSE at or below the reference's own noise says nothing: its efficiency is left at 0.
        table.push_back({s, slope, last.mse, last.relative_mse, last.cpu_seconds,
                         last.mse > 0 ? 1.0 / (last.mse * cpu) : 0.0,
                         last.relative_mse > 0 ? 1.0 / (last.relative_mse * cpu) : 0.0});
    }
    return table;
}

void write_convergence_csv(const std::vector<ConvergenceRow>& rows, const fs::path& csv) {
    std::ofstream out(csv);
    if (!out) throw InputError("--csv: " + csv.string() + ": cannot be written");
    out << "strategy,spp,rmse,mse,relative_mse,seconds,cpu_seconds\n";
    for (const ConvergenceRow& r : rows) {
        out << to_string(r.strategy) << ',' << r.spp << ',' << r.rmse << ',' << r.mse << ',' << r.relative_mse
            << ',' << r.seconds << ',' << r.cpu_seconds << '\n';
    }
    if (!out) throw std::runtime_error(csv.string() + ": write failed");
}

bool plot_convergence(const fs::path& csv, const std::vector<SamplingStrategy>& strategies,
                      const fs::path& png_stem, const std::string& title) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return false;
    // The slope −1/2 is drawn through half the first point of the last strategy, beside the curves.
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    double rmse1 = 0, relative1 = 0, rmse_last = 0, seconds_last = 0;
    const std::string anchor(to_string(strategies.back()));
    while (std::getline(in, line)) {
        if (line.rfind(anchor + ",", 0) != 0) continue;
        double values[6];
        std::size_t at = anchor.size() + 1;
        for (double& v : values) {
            std::size_t used = 0;
            v = std::stod(line.substr(at), &used);
            at += used + 1;
        }
        if (rmse1 == 0) rmse1 = values[1], relative1 = values[3];
        rmse_last = values[1];
        seconds_last = values[5];
    }
    const fs::path script = png_stem.string() + ".gp";
    std::ofstream gp(script);
    gp << "set terminal pngcairo size 640,440 font ',10'\nset termoption noenhanced\n"
       << "set datafile separator ','\nset logscale xy\n"
       << "set grid\nset key outside right\nset title '" << title << "'\n";
    auto plot = [&](const std::string& suffix, const std::string& x_label, int x_column, int y_column,
                    const std::string& y_label, const std::string& guide) {
        gp << "set output '" << png_stem.string() << suffix << "'\nset xlabel '" << x_label
           << "'\nset ylabel '" << y_label << "'\nplot ";
        for (SamplingStrategy s : strategies) {
            gp << "'" << csv.string() << "' using (strcol(1) eq '" << to_string(s) << "' ? $" << x_column
               << " : 1/0):" << y_column << " with linespoints title '" << to_string(s) << "', ";
        }
        gp << guide << " with lines dashtype 2 lc 'black' title '"
           << (y_column == 3 ? "slope -1/2" : "slope -1") << "'\n";
    };
    plot("_spp.png", "samples per pixel", 2, 3, "RMSE to the reference",
         std::to_string(rmse1 * 0.5) + "/sqrt(x)");
    plot("_time.png", "processor time of the render (s)", 7, 3, "RMSE to the reference",
         std::to_string(rmse_last * std::sqrt(seconds_last) * 0.5) + "/sqrt(x)");
    plot("_relative.png", "samples per pixel", 2, 5, "relative MSE to the reference",
         std::to_string(relative1 * 0.5) + "/x");
    gp.close();
    const bool drawn = std::system(("gnuplot '" + script.string() + "'").c_str()) == 0;
    std::error_code ec;
    fs::remove(script, ec);
    return drawn;
}

void print_convergence_study(const RenderScene& prepared, const PathOptions& options,
                             const PinholeCamera& camera, const RenderSettings& settings,
                             const Reference& ref, int max_spp, const std::string& csv) {
    const std::vector<SamplingStrategy> strategies(kAllStrategies.begin(), kAllStrategies.end());
    const auto rows = convergence_study(prepared, options, camera, settings, ref, strategies, max_spp);
    std::printf("%-8s %6s %12s %12s %12s %10s %10s\n", "strategy", "spp", "RMSE", "MSE-noise",
                "rel.MSE-noise", "wall (s)", "cpu (s)");
    for (const ConvergenceRow& r : rows) {
        std::printf("%-8s %6d %12.4e %12.4e %12.4e %10.4f %10.4f\n", to_string(r.strategy).data(), r.spp,
                    r.rmse, r.mse, r.relative_mse, r.seconds, r.cpu_seconds);
    }
    const auto table = efficiency_table(rows);
    double uniform = 0, uniform_relative = 0;
    for (const EfficiencyRow& e : table) {
        if (e.strategy == SamplingStrategy::kUniform)
            uniform = e.efficiency, uniform_relative = e.relative_efficiency;
    }
    std::printf(
        "\nefficiency = 1 / (MSE x processor seconds) at %d spp, and the same with the relative MSE; "
        "slope "
        "of log RMSE against log spp\n",
        max_spp);
    std::printf("%-8s %8s %12s %12s %9s %12s %9s %12s %9s\n", "strategy", "slope", "MSE", "rel. MSE",
                "cpu (s)", "efficiency", "x uniform", "rel. eff.", "x uniform");
    for (const EfficiencyRow& e : table) {
        std::printf("%-8s %8.3f %12.4e %12.4e %9.2f %12.4g %9.3g %12.4g %9.3g\n",
                    to_string(e.strategy).data(), e.slope, e.mse, e.relative_mse, e.cpu_seconds, e.efficiency,
                    uniform > 0 ? e.efficiency / uniform : 0.0, e.relative_efficiency,
                    uniform_relative > 0 ? e.relative_efficiency / uniform_relative : 0.0);
    }
    for (const EfficiencyRow& e : table) {
        if (!(e.mse > 0) || !(e.relative_mse > 0)) {
            std::printf(
                "note: an MSE at or below the reference's own noise (efficiency shown as 0): render "
                "the "
                "reference with more samples (--reference-spp)\n");
            break;
        }
    }
    write_convergence_csv(rows, csv);
    std::filesystem::path stem = csv;
    stem.replace_extension();
    const std::string title = std::filesystem::path(prepared.scene.file).filename().string() + ", " +
                              std::to_string(settings.width) + "x" + std::to_string(settings.height);
    if (plot_convergence(csv, strategies, stem, title)) {
        std::printf("wrote %s, %s_spp.png, %s_time.png and %s_relative.png\n", csv.c_str(), stem.c_str(),
                    stem.c_str(), stem.c_str());
    } else {
        std::printf("wrote %s; gnuplot is not installed, so no plot (apt-get install gnuplot-nox)\n",
                    csv.c_str());
    }
}

void run_convergence_study(const RenderScene& prepared, const PathOptions& options, const PinholeCamera& camera,
                           const RenderSettings& settings, const ConvergenceRequest& request) {
    check_writable("--csv", request.csv);
    std::printf("converged reference: %d spp (MIS), %dx%d ...\n", request.reference_spp, settings.width,
                settings.height);
    std::fflush(stdout);
    const Reference ref =
        converged_reference(prepared, options, camera, settings, request.reference_spp, request.cache);
    std::printf("  %s %s; its own noise: MSE %.3e (RMSE %.3e)\n", ref.cached ? "read" : "rendered and wrote",
                ref.file.string().c_str(), ref.noise_mse, std::sqrt(ref.noise_mse));
    print_convergence_study(prepared, options, camera, settings, ref, request.max_spp, request.csv);
}

}  // namespace rt
