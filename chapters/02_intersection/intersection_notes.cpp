#include "intersection_notes.hpp"

#include <variant>

#include "leak_probe.hpp"
#include "rt/core/formatted.hpp"

namespace rt {
namespace {

std::string world_note(const World& world, const IntersectionRun& run) {
    return formatted("world: %.0f primitives (%.0f triangles)", double(world.primitive_count()),
                     double(world.triangle_count())) +
           (run.options.acceleration != Acceleration::kNone
                ? formatted(", BVH of %.0f binary nodes and %.0f wide ones",
                            double(world.bvh().nodes().size()), double(world.wide_bvh().nodes().size())) +
                      formatted(" (%.0f KiB in all) built in %.1f ms",
                                double(world.acceleration_bytes()) / 1024, run.build_seconds * 1e3)
                : std::string(", no acceleration: every ray tests every primitive"));
}

std::string cost_note(const IntersectionRun& run, const RenderResult& result,
                      const std::optional<MeanTraversalCost>& cost) {
    const double camera_rays = double(result.rays[RayKind::kCamera]);
    return "triangle test: " + std::string(to_string(run.options.triangle_test)) +
           ", acceleration: " + std::string(to_string(run.options.acceleration)) +
           formatted(": %.1f ns per camera ray (render time x threads / rays); ",
                     camera_rays > 0 ? result.seconds * 1e9 * run.threads / camera_rays : 0.0) +
           (cost ? formatted("per ray %.1f boxes and %.1f primitives tested", cost->nodes, cost->primitives)
                 : std::string("boxes and primitives per ray not measured (interrupted)"));
}

}  // namespace

std::vector<std::string> intersection_notes(const Scene& scene, const World& world,
                                            const IntersectionRun& run, const RenderResult& result,
                                            const std::optional<MeanTraversalCost>& cost) {
    std::vector<std::string> notes{
        "showing " + std::string(to_string(run.show)) + "; materials are not shaded before chapter 03",
        world_note(world, run), cost_note(run, result, cost)};
    if (!cost) return notes;  // interrupted: no leak probe either
    for (const Shape& shape : scene.shapes) {
        const auto* mesh = std::get_if<MeshShape>(&shape.geometry);
        if (!mesh) continue;
        if (!is_closed(*mesh)) {
            notes.push_back(shape.place + ": the mesh is not closed; no leak probe");
            continue;
        }
        const LeakProbe probe = probe_leaks(*mesh, run.options.triangle_test);
        notes.push_back(shape.place + formatted(": leak probe, %.0f of %.0f rays from inside the closed mesh "
                                                "(aimed at its vertices and edges) escaped",
                                                double(probe.escaped), double(probe.rays)));
    }
    return notes;
}

}  // namespace rt
