#include "offset_study_report.hpp"

#include <cstdio>
#include <fstream>

#include "offset_study.hpp"
#include "rt/core/formatted.hpp"
#include "rt/io/image_io.hpp"
#include "scene_scale.hpp"

namespace rt {
namespace {

void print_study(const std::vector<OffsetStudyRow>& rows, const RenderSettings& settings,
                 const std::string& csv) {
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
            to_string(r.offset.method).data(), eps ? formatted("%g", double(r.offset.epsilon)).c_str() : "-",
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

void run_offset_study(const Scene& scene, const OffsetStudyRequest& request, Real scale, Real epsilon,
                      const RenderSettings& settings) {
    if (!request.csv.empty()) check_writable("--csv", request.csv);
    std::vector<Real> scales;
    for (Real s : request.scales) {
        check_scale(scene, s * scale, "--study-scales (times --scale)");
        scales.push_back(s * scale);
    }
    const std::vector<RayOffset> methods{
        {OffsetMethod::kNone, epsilon}, {OffsetMethod::kEpsilon, epsilon}, {OffsetMethod::kRobust, epsilon}};
    print_study(offset_study(scene, scales, methods, settings), settings, request.csv);
}

}  // namespace rt
