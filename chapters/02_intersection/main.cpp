// Chapter 02: intersection. Renders each camera ray's nearest hit (by normal, distance or cost), with the
// triangle test and the acceleration structure chosen on the command line, and reports what each costs:
// time per ray, tests per ray, and the rays that leak through a closed mesh.
#include <chrono>
#include <cstdio>
#include <string>
#include <variant>

#include "01_ray_generation/camera.hpp"
#include "intersection_render.hpp"
#include "leak_probe.hpp"
#include "mesh_generator.hpp"
#include "rt/app.hpp"
#include "world.hpp"

namespace {

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace rt;
    std::string show = "normal";
    std::string triangle_test = "watertight";
    std::string accel = "bvh";
    std::string mesh_out;
    const ChapterInfo chapter{"ch02_intersection",
                              "Chapter 02: the nearest intersection of a ray with a scene",
                              "ch02_default.json", EffectSet{Effect::kCameraRays}};
    auto flags = [&](CLI::App& app) {
        app.add_option("--show", show,
                       "What each pixel shows: normal|distance|cost (boxes and primitives tested)")
            ->check(CLI::IsMember({"normal", "distance", "cost"}));
        app.add_option("--triangle-test", triangle_test, "Ray–triangle test: watertight|moller")
            ->check(CLI::IsMember({"watertight", "moller"}));
        app.add_option("--accel", accel,
                       "Acceleration: bvh (4-wide, collapsed from the binary one)|binary (the binary BVH "
                       "itself)|none (test every primitive)")
            ->check(CLI::IsMember({"bvh", "binary", "none"}));
        app.add_option(
            "--write-mesh", mesh_out,
            "Write the default scene's mesh (icosphere, 3 subdivisions, radii jittered by 5%) as OBJ, "
            "and exit");
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        if (!mesh_out.empty()) {
            MeshShape mesh = make_icosphere(3);
            jitter_radii(mesh, Real(0.05), 2);
            write_obj(mesh, mesh_out);
            std::printf("wrote %s: %zu vertices, %zu triangles\n", mesh_out.c_str(), mesh.positions.size(),
                        mesh.triangles.size());
            return std::nullopt;
        }
        const WorldOptions options{
            triangle_test == "moller" ? TriangleTest::kMollerTrumbore : TriangleTest::kWatertight,
            accel == "none" ? Acceleration::kNone
                            : (accel == "binary" ? Acceleration::kBinaryBvh : Acceleration::kBvh)};
        const auto build_start = std::chrono::steady_clock::now();
        const World world(context.scene, options);
        const double build_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
        const RenderSettings& settings = context.settings;
        const PinholeCamera camera =
            make_pinhole_camera(context.scene.camera, settings.width, settings.height);
        // Distances shown as exp(−t / s), s half the distance to the look-at point: exp(−2) there.
        const Real distance_scale = glm::length(context.scene.camera.at - context.scene.camera.from) / 2;
        const RenderResult result =
            render_intersections(world, camera, show_mode_from_string(show), distance_scale, settings);
        // Measured apart from the render, and not at all once it was interrupted.
        const std::optional<MeanTraversalCost> cost =
            result.interrupted ? std::nullopt : mean_traversal_cost(world, camera);

        ChapterRun run{result, {}, std::nullopt};
        const double camera_rays = double(result.rays[RayKind::kCamera]);
        run.notes.push_back("showing " + show + "; materials are not shaded before chapter 03");
        run.notes.push_back(format("world: %.0f primitives (%.0f triangles)", double(world.primitive_count()),
                                   double(world.triangle_count())) +
                            (options.acceleration != Acceleration::kNone
                                 ? format(", BVH of %.0f binary nodes and %.0f wide ones",
                                          double(world.bvh().nodes().size()),
                                          double(world.wide_bvh().nodes().size())) +
                                       format(" (%.0f KiB in all) built in %.1f ms",
                                          double(world.acceleration_bytes()) / 1024, build_seconds * 1e3)
                                 : std::string(", no acceleration: every ray tests every primitive")));
        run.notes.push_back(
            "triangle test: " + triangle_test + ", acceleration: " + accel +
            format(": %.1f ns per camera ray (render time x threads / rays); ",
                   camera_rays > 0 ? result.seconds * 1e9 * settings.threads / camera_rays : 0.0) +
            (cost ? format("per ray %.1f boxes and %.1f primitives tested", cost->nodes, cost->primitives)
                  : std::string("boxes and primitives per ray not measured (interrupted)")));
        for (const Shape& shape : context.scene.shapes) {
            if (!cost) break;  // interrupted: no leak probe either
            const auto* mesh = std::get_if<MeshShape>(&shape.geometry);
            if (!mesh) continue;
            if (!is_closed(*mesh)) {
                run.notes.push_back(shape.place + ": the mesh is not closed; no leak probe");
                continue;
            }
            const LeakProbe probe = probe_leaks(*mesh, options.triangle_test);
            run.notes.push_back(shape.place +
                                format(": leak probe, %.0f of %.0f rays from inside the closed mesh "
                                       "(aimed at its vertices and edges) escaped",
                                       double(probe.escaped), double(probe.rays)));
        }
        return run;
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
