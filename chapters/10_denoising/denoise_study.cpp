#include "denoise_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "07_bsdf_refraction/bsdf_render.hpp"
#include "07_bsdf_refraction/depth_study.hpp"
#include "09_participating_media/volume_path_tracer.hpp"
#include "feature_buffers.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/io/image_io.hpp"
#include "ssim.hpp"

namespace rt {
namespace {

constexpr Denoiser kDenoisers[] = {Denoiser::kNone, Denoiser::kBilateral, Denoiser::kAtrous};

RenderSettings with(const RenderSettings& settings, int spp, std::uint64_t seed) {
    RenderSettings s = settings;
    s.samples_per_pixel = spp;
    s.seed = seed;
    s.progress = ProgressStyle::kNone;
    return s;
}

// The filter run three times: its image and its median time.
Denoised timed_denoise(const FeatureBuffers& buffers, Denoiser denoiser, const DenoiseSettings& settings) {
    std::vector<double> times;
    Denoised out;
    for (int i = 0; i < 3; ++i) {
        out = denoise(buffers, denoiser, settings);
        times.push_back(out.seconds);
    }
    std::sort(times.begin(), times.end());
    out.seconds = times[1];
    return out;
}

// Plain path tracing (chapter 07's renderer, no features) at `spp`: its relative MSE and time.
struct PlainPoint {
    int spp;
    double relative_mse, seconds;
    Image image;
};

PlainPoint plain_point(const Scene& scene, const RenderSettings& settings, const PathOptions& options,
                       int spp, const Image& reference) {
    const RenderResult r = render_with_media(Renderer::kPaths, scene, options.simulated,
                                             with(settings, spp, settings.seed), options);
    return {spp, compare(r.image, reference).relative_mse, r.seconds, r.image};
}

// The spp at which plain path tracing reaches `target`, interpolated log-log between the two points that
// bracket it, and its time (linear in spp between them); past the last point, the 1/N law from it.
struct EqualError {
    double spp, seconds;
    bool extrapolated, below_first;
};

EqualError equal_error(const std::vector<PlainPoint>& points, double target) {
    if (target >= points.front().relative_mse)
        return {double(points.front().spp), points.front().seconds, false, true};
    for (std::size_t k = 1; k < points.size(); ++k) {
        const PlainPoint &a = points[k - 1], &b = points[k];
        if (b.relative_mse > target) continue;
        const double t = (std::log(target) - std::log(a.relative_mse)) /
                         (std::log(b.relative_mse) - std::log(a.relative_mse));
        const double spp =
            std::exp(std::log(double(a.spp)) + t * (std::log(double(b.spp)) - std::log(double(a.spp))));
        const double seconds = a.seconds + (spp - a.spp) * (b.seconds - a.seconds) / double(b.spp - a.spp);
        return {spp, seconds, false, false};
    }
    const PlainPoint& last = points.back();
    const double spp = last.spp * last.relative_mse / target;
    return {spp, last.seconds * spp / last.spp, true, false};
}

// Over `rect`: the mean over the runs of the relative squared error, and the relative variance of the runs
// about their own mean (unbiased, K − 1); MSE − variance estimates bias².
struct BiasSplit {
    double mse = 0, variance = 0;
};

BiasSplit bias_split(const std::vector<Image>& runs, const Image& reference, const PixelRect& rect) {
    BiasSplit b;
    const double k = double(runs.size());
    for (int y = rect.y0; y < rect.y1; ++y) {
        for (int x = rect.x0; x < rect.x1; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double r = reference.at(x, y)[c], scale = 1.0 / (r * r + 0.01);
                double mean = 0, squares = 0, error = 0;
                for (const Image& image : runs) {
                    const double v = image.at(x, y)[c];
                    mean += v;
                    squares += v * v;
                    error += (v - r) * (v - r);
                }
                mean /= k;
                b.mse += scale * error / k;
                b.variance += scale * std::max(0.0, squares - k * mean * mean) / (k - 1);
            }
        }
    }
    const double n = 3.0 * double(rect.x1 - rect.x0) * double(rect.y1 - rect.y0);
    b.mse /= n;
    b.variance /= n;
    return b;
}

// Each 2×2 block averaged: half the size, for a small picture of the whole image.
Image half_size(const Image& image) {
    Image out(std::max(1, image.width() / 2), std::max(1, image.height() / 2));
    for (int y = 0; y < out.height(); ++y) {
        for (int x = 0; x < out.width(); ++x) {
            Color sum(0);
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i)
                    sum += image.at(std::min(2 * x + i, image.width() - 1),
                                    std::min(2 * y + j, image.height() - 1));
            out.at(x, y) = sum / Real(4);
        }
    }
    return out;
}

Image upscale(const Image& image, int factor) {
    Image out(image.width() * factor, image.height() * factor);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) out.at(x, y) = image.at(x / factor, y / factor);
    return out;
}

// Images side by side, a gap of 2 black pixels between them.
Image side_by_side(const std::vector<Image>& images) {
    int width = 0;
    for (const Image& i : images) width += i.width() + 2;
    Image out(width - 2, images.front().height());
    int x0 = 0;
    for (const Image& i : images) {
        for (int y = 0; y < i.height(); ++y)
            for (int x = 0; x < i.width(); ++x) out.at(x0 + x, y) = i.at(x, y);
        x0 += i.width() + 2;
    }
    return out;
}

std::string slug(const char* name) {
    std::string s;
    for (const char* c = name; *c; ++c) {
        if (std::isalnum(static_cast<unsigned char>(*c)))
            s += *c;
        else if (!s.empty() && s.back() != '_')
            s += '_';
    }
    while (!s.empty() && s.back() == '_') s.pop_back();
    return s;
}

// A row of the sweeps: the whole image's relative MSE and SSIM, and the relative MSE of two regions where the
// guides matter (the rods, the caustic).
void print_sweep_row(const char* parameter, const std::string& value, const Image& image, double seconds,
                     const Image& reference) {
    const int w = reference.width(), h = reference.height();
    const std::vector<StudyRegion>& regions = cornell_regions();
    std::printf("  %-17s %-6s %12.4e %8.4f %12.4e %12.4e %9.3f\n", parameter, value.c_str(),
                compare(image, reference).relative_mse, ssim(image, reference),
                compare(image, reference, pixels_of(regions[3], w, h)).relative_mse,
                compare(image, reference, pixels_of(regions[0], w, h)).relative_mse, seconds);
}

std::string number(Real v) {
    if (std::isinf(v)) return "off";
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
}

}  // namespace

const std::vector<StudyRegion>& cornell_regions() {
    static const std::vector<StudyRegion> regions{
        {"caustic under the glass sphere", 0.55, 0.84, 0.73, 0.95},
        {"image refracted in the sphere", 0.52, 0.65, 0.72, 0.82},
        {"the lamp's edge", 0.37, 0.09, 0.50, 0.19},
        {"fine geometry (the rods)", 0.62, 0.55, 0.78, 0.68},
    };
    return regions;
}

PixelRect pixels_of(const StudyRegion& region, int width, int height) {
    PixelRect r{int(region.x0 * width), int(region.y0 * height), int(std::ceil(region.x1 * width)),
                int(std::ceil(region.y1 * height))};
    r.x1 = std::clamp(r.x1, r.x0 + 1, width);
    r.y1 = std::clamp(r.y1, r.y0 + 1, height);
    return r;
}

Image crop(const Image& image, const PixelRect& rect) {
    Image out(rect.x1 - rect.x0, rect.y1 - rect.y0);
    for (int y = rect.y0; y < rect.y1; ++y)
        for (int x = rect.x0; x < rect.x1; ++x) out.at(x - rect.x0, y - rect.y0) = image.at(x, y);
    return out;
}

namespace {

// What the study's sections share: its inputs, the reference, and section 1's render and filters.
struct StudyRun {
    const Scene& scene;
    const RenderSettings& settings;
    const PathOptions& options;
    const DenoiseSettings& denoise_settings;
    const StudyOptions& study;
    int spp;  // the run's
    Image reference;
    FeatureRender render;            // the run's render with its features
    std::vector<Denoised> denoised;  // each of kDenoisers on it
    double render_seconds = 0, plain_seconds = 0, noisy_error = 0;
};

// 1. Each denoiser at the run's spp.
void denoisers_at_run_spp(StudyRun& r) {
    // The times of a render with features and of plain path tracing at the run's spp, measured alternately
    // (three of each, medians), so that the machine's load falls on both alike.
    std::vector<double> feature_times, plain_times;
    for (int i = 0; i < 3; ++i) {
        r.render = render_features(r.scene, with(r.settings, r.spp, r.settings.seed), r.options);
        feature_times.push_back(r.render.result.seconds);
        plain_times.push_back(render_with_media(Renderer::kPaths, r.scene, r.options.simulated,
                                                with(r.settings, r.spp, r.settings.seed), r.options)
                                  .seconds);
    }
    std::sort(feature_times.begin(), feature_times.end());
    std::sort(plain_times.begin(), plain_times.end());
    r.render_seconds = feature_times[1];
    r.plain_seconds = plain_times[1];
    for (Denoiser d : kDenoisers)
        r.denoised.push_back(timed_denoise(r.render.buffers, d, r.denoise_settings));
    r.noisy_error = compare(r.render.buffers.colour, r.reference).relative_mse;
    std::printf(
        "1. the denoisers at %d spp (render %.3f s with the features, %.3f s without: medians of 3, taken "
        "alternately; filter: median of 3)\n",
        r.spp, r.render_seconds, r.plain_seconds);
    std::printf("  %-10s %12s %12s %8s %13s %9s %9s %14s\n", "denoiser", "rel. MSE", "RMSE", "SSIM",
                "mean error", "filter s", "total s", "x closer");
    for (std::size_t i = 0; i < r.denoised.size(); ++i) {
        const ErrorMetrics e = compare(r.denoised[i].image, r.reference);
        std::printf("  %-10s %12.4e %12.4e %8.4f %+13.4e %9.3f %9.3f %14.2f\n",
                    to_string(kDenoisers[i]).data(), e.relative_mse, e.rmse,
                    ssim(r.denoised[i].image, r.reference), e.mean_error, r.denoised[i].seconds,
                    r.render_seconds + r.denoised[i].seconds, r.noisy_error / e.relative_mse);
    }
    std::printf("\n");
    std::fflush(stdout);
}

// 2. Equal error: plain path tracing at doubling spp, up to `cap`.
std::vector<PlainPoint> equal_error_table(const StudyRun& r, int cap) {
    std::vector<PlainPoint> points{plain_point(r.scene, r.settings, r.options, r.spp, r.reference)};
    double hardest = r.noisy_error;
    for (std::size_t i = 1; i < r.denoised.size(); ++i)
        hardest = std::min(hardest, compare(r.denoised[i].image, r.reference).relative_mse);
    while (points.back().relative_mse > hardest && points.back().spp * 2 <= cap)
        points.push_back(plain_point(r.scene, r.settings, r.options, points.back().spp * 2, r.reference));
    std::printf("2. equal error: plain path tracing (no features, no filter) at doubling spp\n");
    std::printf("  %8s %12s %9s\n", "spp", "rel. MSE", "time s");
    for (const PlainPoint& p : points) std::printf("  %8d %12.4e %9.3f\n", p.spp, p.relative_mse, p.seconds);
    std::printf("  %-10s %12s %14s %14s %14s %14s\n", "denoiser", "rel. MSE", "plain spp", "measured s",
                "linear s", "x sooner");
    for (std::size_t i = 1; i < r.denoised.size(); ++i) {
        const double target = compare(r.denoised[i].image, r.reference).relative_mse;
        const EqualError eq = equal_error(points, target);
        const double total = r.render_seconds + r.denoised[i].seconds;
        // Path tracing's time is linear in spp: the plain render's median at the run's spp, scaled.
        const double linear = r.plain_seconds * eq.spp / r.spp;
        if (eq.below_first) {
            std::printf("  %-10s %12.4e %14s %14s %14s %14s\n", to_string(kDenoisers[i]).data(), target,
                        "< run's", "-", "-", "loses");
            continue;
        }
        std::printf("  %-10s %12.4e %13.0f%s %14.3f %14.3f %14.2f\n", to_string(kDenoisers[i]).data(), target,
                    eq.spp, eq.extrapolated ? "*" : " ", eq.seconds, linear, linear / total);
    }
    std::printf(
        "  (* past the last render: the 1/N law from it; measured: interpolated between the renders above;\n"
        "   linear: the plain median at %d spp times plain spp / %d; x sooner = linear / (render with "
        "features "
        "+ filter))\n\n",
        r.spp, r.spp);
    std::fflush(stdout);
    return points;
}

// 3. The bias over independent runs: each denoiser's image of each run.
std::vector<std::vector<Image>> bias_over_runs(const StudyRun& r) {
    std::vector<std::vector<Image>> runs(std::size(kDenoisers));
    for (int k = 0; k < r.study.runs; ++k) {
        const FeatureRender run = render_features(
            r.scene, with(r.settings, r.spp, r.settings.seed + 1 + std::uint64_t(k)), r.options);
        for (std::size_t i = 0; i < std::size(kDenoisers); ++i)
            runs[i].push_back(denoise(run.buffers, kDenoisers[i], r.denoise_settings).image);
    }
    std::printf(
        "3. bias: %d independent runs at %d spp; relative terms (each over r^2 + 0.01), MSE = bias^2 + "
        "variance\n",
        r.study.runs, r.spp);
    std::printf("  %-10s %12s %12s %12s %10s\n", "denoiser", "rel. MSE", "variance", "bias^2", "bias share");
    const PixelRect whole{0, 0, r.reference.width(), r.reference.height()};
    for (std::size_t i = 0; i < std::size(kDenoisers); ++i) {
        const BiasSplit b = bias_split(runs[i], r.reference, whole);
        std::printf("  %-10s %12.4e %12.4e %12.4e %9.1f%%\n", to_string(kDenoisers[i]).data(), b.mse,
                    b.variance, b.mse - b.variance, 100.0 * (b.mse - b.variance) / b.mse);
    }
    std::printf("\n");
    return runs;
}

// 4. The failure regions, against plain path tracing at the spp that matches the best filter overall.
void failure_regions(const StudyRun& r, const std::vector<PlainPoint>& points, int cap,
                     const std::vector<std::vector<Image>>& runs) {
    const EqualError matched_error =
        equal_error(points, compare(r.denoised[2].image, r.reference).relative_mse);
    // At most the doubling renders' cap: past it the equal-error spp is extrapolated, and too costly to
    // render.
    const int matched_spp = std::clamp(int(std::lround(matched_error.spp)), 1, cap);
    const PlainPoint matched = plain_point(r.scene, r.settings, r.options, matched_spp, r.reference);
    std::printf(
        "4. regions: relative MSE of each; plain path tracing at %d spp, which reaches atrous's error on the "
        "whole image%s;\n   SSIM; atrous's bias share over the runs. Where atrous is worse than the plain "
        "render, it does worse there than its average\n",
        matched.spp, matched_error.extrapolated ? " (capped: it needs more)" : "");
    std::printf("  %-31s %11s %11s %11s %11s %8s %8s %7s\n", "region", "noisy", "bilateral", "atrous",
                "plain", "SSIM at.", "SSIM pl.", "bias");
    for (const StudyRegion& region : cornell_regions()) {
        const PixelRect rect = pixels_of(region, r.reference.width(), r.reference.height());
        const Image ref = crop(r.reference, rect);
        std::printf("  %-31s", region.name);
        for (const Denoised& d : r.denoised)
            std::printf(" %11.4e", compare(d.image, r.reference, rect).relative_mse);
        std::printf(" %11.4e", compare(matched.image, r.reference, rect).relative_mse);
        const BiasSplit b = bias_split(runs[2], r.reference, rect);
        std::printf(" %8.4f %8.4f %6.0f%%\n", ssim(crop(r.denoised[2].image, rect), ref),
                    ssim(crop(matched.image, rect), ref), 100.0 * (b.mse - b.variance) / b.mse);
        if (!r.study.crops.empty()) {
            std::vector<Image> strip{upscale(ref, 2)};
            for (const Denoised& d : r.denoised) strip.push_back(upscale(crop(d.image, rect), 2));
            write_png(side_by_side(strip),
                      std::filesystem::path(r.study.crops) / ("ch10_" + slug(region.name) + ".png"));
        }
    }
    if (!r.study.crops.empty()) {
        std::vector<Image> strip{half_size(r.reference)};
        for (const Denoised& d : r.denoised) strip.push_back(half_size(d.image));
        write_png(side_by_side(strip), std::filesystem::path(r.study.crops) / "ch10_whole.png");
        std::printf(
            "  wrote the strips (reference | noisy | bilateral | atrous; the regions at twice their size, "
            "the "
            "whole image at half) into %s\n",
            r.study.crops.c_str());
    }
    std::printf("\n");
}

// 5. Sweeps, one parameter at a time from the settings given.
void sweeps(const StudyRun& r) {
    std::printf("5. sweeps at %d spp, one parameter at a time\n", r.spp);
    std::printf("  %-17s %-6s %12s %8s %12s %12s %9s\n", "parameter", "value", "rel. MSE", "SSIM", "rods",
                "caustic", "filter s");
    auto sweep_edges = [&](Denoiser d, const char* name, Real EdgeStopping::*member,
                           std::initializer_list<Real> values) {
        for (Real v : values) {
            DenoiseSettings s = r.denoise_settings;
            EdgeStopping& edges = d == Denoiser::kAtrous ? s.atrous.edges : s.bilateral.edges;
            edges.*member = v;
            const Denoised out = denoise(r.render.buffers, d, s);
            print_sweep_row(name, number(v), out.image, out.seconds, r.reference);
        }
    };
    for (int levels : {1, 2, 3, 4, 5, 6, 7}) {
        DenoiseSettings s = r.denoise_settings;
        s.atrous.levels = levels;
        const Denoised out = denoise(r.render.buffers, Denoiser::kAtrous, s);
        print_sweep_row("atrous levels", std::to_string(levels), out.image, out.seconds, r.reference);
    }
    const Real off = kInfinity;
    sweep_edges(Denoiser::kAtrous, "atrous colour", &EdgeStopping::colour, {0.5, 1, 2, 4, 8, off});
    sweep_edges(Denoiser::kAtrous, "atrous normal", &EdgeStopping::normal, {0.1, 0.3, 1, off});
    sweep_edges(Denoiser::kAtrous, "atrous depth", &EdgeStopping::depth, {0.01, 0.05, 0.2, off});
    sweep_edges(Denoiser::kAtrous, "atrous albedo", &EdgeStopping::albedo, {0.03, 0.1, 0.3, off});
    for (Real sigma : {1.0f, 2.0f, 3.0f, 5.0f}) {
        DenoiseSettings s = r.denoise_settings;
        s.bilateral.spatial = sigma;
        const Denoised out = denoise(r.render.buffers, Denoiser::kBilateral, s);
        print_sweep_row("bilateral sigma_s", number(sigma), out.image, out.seconds, r.reference);
    }
    sweep_edges(Denoiser::kBilateral, "bilateral colour", &EdgeStopping::colour, {0.5, 1, 2, 4, off});
}

}  // namespace

void run_denoise_study(const Scene& scene, const RenderSettings& settings, const PathOptions& options,
                       const DenoiseSettings& denoise_settings, const StudyOptions& study) {
    // Its outputs are probed before it renders (its cached reference: chapter 07's depth study).
    if (!study.crops.empty())
        check_writable("--crops", std::filesystem::path(study.crops) / "ch10_whole.png");
    const int spp = settings.samples_per_pixel;
    std::printf("denoising study: %s, %dx%d, %d spp, seed %llu, %d threads\n", scene.file.c_str(),
                settings.width, settings.height, spp, static_cast<unsigned long long>(settings.seed),
                settings.threads);
    std::printf("reference: %d spp, chapter 07's renderer, seed %llu ...\n", study.reference_spp,
                static_cast<unsigned long long>(settings.seed + 1000));
    std::fflush(stdout);
    bool cached = false;
    Image reference = glass_depth_reference(scene, with(settings, spp, settings.seed), options,
                                            study.reference_spp, study.cache, cached);
    std::printf("  %s\n\n", cached ? "read from the cache" : "rendered and cached");
    StudyRun run{scene, settings, options, denoise_settings, study, spp, std::move(reference), {}, {}};
    denoisers_at_run_spp(run);
    const int cap = std::max(spp, study.reference_spp / 4);
    const std::vector<PlainPoint> points = equal_error_table(run, cap);
    const std::vector<std::vector<Image>> runs = bias_over_runs(run);
    failure_regions(run, points, cap, runs);
    if (study.sweeps) sweeps(run);
}

}  // namespace rt
