// Chapter 03: shadow rays. Point lights light diffuse surfaces (E = I cos θ / r², L = (ρ / π) E) wherever a
// shadow ray reaches them; `--offset none|epsilon|robust` chooses how a shadow ray leaves the surface, and
// `--offset-study` measures what each method costs and gets wrong at scales from 1e-3 to 1e5.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "offset_study.hpp"
#include "ray_offset.hpp"
#include "rt/app.hpp"
#include "rt/errors.hpp"
#include "rt/image_io.hpp"
#include "scene_scale.hpp"
#include "shadow_render.hpp"

namespace {

std::string format(const char* pattern, double a, double b = 0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

void print_study(const std::vector<rt::OffsetStudyRow>& rows, const rt::RenderSettings& settings,
                 const std::string& csv) {
    using namespace rt;
    std::printf("ray offsets, %dx%d, %d spp, %d threads: shadow rays judged against the exact visibility\n",
                settings.width, settings.height, settings.samples_per_pixel, settings.threads);
    std::printf("%8s %-8s %9s %11s %10s %10s %10s %10s %9s %10s\n", "scale", "offset", "epsilon",
                "shadow rays", "self-hits", "acne px", "leak px", "mean", "time (s)", "offset ns");
    std::ofstream out;
    if (!csv.empty()) {
        out.open(csv);
        out << "scale,offset,epsilon,shadow_rays,self_hits,acne_pixels,leak_pixels,mean,seconds,offset_ns\n";
    }
    for (const OffsetStudyRow& r : rows) {
        const bool eps = r.offset.method == OffsetMethod::kEpsilon;
        std::printf(
            "%8g %-8s %9s %11llu %10llu %10llu %10llu %10.5f %9.4f %10.2f\n", double(r.scale),
            to_string(r.offset.method).data(), eps ? format("%g", double(r.offset.epsilon)).c_str() : "-",
            static_cast<unsigned long long>(r.shadow_rays), static_cast<unsigned long long>(r.self_hits),
            static_cast<unsigned long long>(r.acne_pixels), static_cast<unsigned long long>(r.leak_pixels),
            r.mean, r.seconds, r.offset_ns);
        if (out) {
            out << r.scale << ',' << to_string(r.offset.method) << ',' << (eps ? r.offset.epsilon : 0) << ','
                << r.shadow_rays << ',' << r.self_hits << ',' << r.acne_pixels << ',' << r.leak_pixels << ','
                << r.mean << ',' << r.seconds << ',' << r.offset_ns << '\n';
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace rt;
    std::string offset_name = "robust";
    Real epsilon = Real(1e-4);
    Real scale = 1;
    bool study = false;
    std::vector<Real> study_scales{Real(1e-3), Real(1), Real(1e3), Real(1e5)};
    std::string csv;
    const ChapterInfo chapter{"ch03_shadow_rays", "Chapter 03: point lights, shadow rays and ray offsets",
                              "ch03_default.json", kShadowChapterEffects};
    auto flags = [&](CLI::App& app) {
        CLI::Option* offset_flag =
            app.add_option("--offset", offset_name, "How a shadow ray leaves its surface: none|epsilon|robust")
                ->check(CLI::IsMember({"none", "epsilon", "robust"}));
        app.add_option(
            "--scale", scale,
            "Multiply every length of the scene by this, in [1e-12, 1e12] (intensities by its square)");
        CLI::Option* study_flag = app.add_flag(
            "--offset-study", study, "Count self-hits, acne and leak pixels and time each offset at each of --study-scales");
        app.add_option("--epsilon", epsilon, "The fixed distance of --offset epsilon and of the study's (default 1e-4)")
            ->check(only_with({{offset_flag, {"epsilon"}}, {study_flag}}));
        app.add_option("--study-scales", study_scales,
                       "With --offset-study: the scales (default 1e-3 1 1e3 1e5)")->check(only_with({{study_flag}}));
        app.add_option("--csv", csv, "With --offset-study: also write the table as CSV")->check(only_with({{study_flag}}));
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        if (!(epsilon > 0 && std::isfinite(epsilon))) {
            throw InputError("--epsilon: must be a finite number > 0, got " + format("%g", double(epsilon)));
        }
        const RayOffset offset{offset_method_from_string(offset_name), epsilon};
        const RenderSettings& settings = context.settings;
        if (study) {
            if (!csv.empty()) check_writable("--csv", csv);
            std::vector<Real> scales;
            for (Real s : study_scales) {
                check_scale(context.scene, s * scale, "--study-scales (times --scale)");
                scales.push_back(s * scale);
            }
            const std::vector<RayOffset> methods{{OffsetMethod::kNone, epsilon},
                                                 {OffsetMethod::kEpsilon, epsilon},
                                                 {OffsetMethod::kRobust, epsilon}};
            print_study(offset_study(context.scene, scales, methods, settings), settings, csv);
            return std::nullopt;
        }
        const Scene scene = scale_scene(context.scene, scale);
        const World world(scene);
        const PinholeCamera camera = make_pinhole_camera(scene.camera, settings.width, settings.height);
        const ShadowOptions options = shadow_options(context.simulated, offset);
        ChapterRun run{render_shadows(world, scene, camera, options, settings), {}, std::nullopt};
        std::string method = "ray offset: " + offset_name;
        if (offset.method == OffsetMethod::kEpsilon) method += format(" (epsilon %g)", double(epsilon));
        if (scale != 1) method += format(", scene scaled by %g", double(scale));
        run.notes.push_back(method);
        const double camera_rays = double(run.result.rays[RayKind::kCamera]);
        run.notes.push_back(
            format("%.0f point lights, %.3f shadow rays per camera ray", double(scene.point_lights.size()),
                   camera_rays > 0 ? double(run.result.rays[RayKind::kShadow]) / camera_rays : 0));
        for (std::string& note : shading_notes(scene)) run.notes.push_back(std::move(note));
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
