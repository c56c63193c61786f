// Chapter 02: intersection. Renders each camera ray's nearest hit (by normal, distance or cost), with the
// triangle test and the acceleration structure chosen on the command line, and reports what each costs:
// time per ray, tests per ray, and the rays that leak through a closed mesh.
#include <chrono>
#include <string>

#include "01_ray_generation/camera.hpp"
#include "intersection_notes.hpp"
#include "intersection_render.hpp"
#include "mesh_generator.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/run/app.hpp"
#include "world.hpp"

int main(int argc, char** argv) {
    using namespace rt;
    ShowMode show = ShowMode::kNormal;
    WorldOptions options;
    std::string mesh_out, torus_out;
    const ChapterInfo chapter{"ch02_intersection",
                              "Chapter 02: the nearest intersection of a ray with a scene",
                              "ch02_default.json", EffectSet{Effect::kCameraRays}};
    auto flags = [&](CLI::App& app) {
        add_enum_option(
            app, show,
            "What each pixel shows: " + joined_names<ShowMode>() + " (boxes and primitives tested)");
        add_enum_option(app, options.triangle_test, "Ray–triangle test: " + joined_names<TriangleTest>());
        add_enum_option(app, options.acceleration,
                        "Acceleration: bvh (4-wide, collapsed from the binary one)|binary (the binary BVH "
                        "itself)|none (test every primitive)");
        app.add_option(
            "--write-mesh", mesh_out,
            "Write the default scene's mesh (icosphere, 3 subdivisions, radii jittered by 5%) as OBJ, "
            "and exit");
        app.add_option(
            "--write-torus", torus_out,
            "Write chapter 04's smooth torus (with normals and texture coordinates) as OBJ, or PLY for a "
            "name ending in .ply, and exit");
    };
    auto render = [&](const RunContext& context) -> std::optional<ChapterRun> {
        if (!mesh_out.empty() || !torus_out.empty()) {
            if (!mesh_out.empty()) write_default_mesh(mesh_out);
            if (!torus_out.empty()) write_smooth_torus(torus_out);
            return std::nullopt;
        }
        const auto build_start = std::chrono::steady_clock::now();
        const World world(context.scene, options);
        const std::chrono::duration<double> build_time = std::chrono::steady_clock::now() - build_start;
        const RenderSettings& settings = context.settings;
        const PinholeCamera camera =
            make_pinhole_camera(context.scene.camera, settings.width, settings.height);
        // Distances shown as exp(−t / s), s half the distance to the look-at point: exp(−2) there.
        const Real distance_scale = glm::length(context.scene.camera.at - context.scene.camera.from) / 2;
        const RenderResult result = render_intersections(world, camera, show, distance_scale, settings);
        // Measured apart from the render, and not at all once it was interrupted.
        const std::optional<MeanTraversalCost> cost =
            result.interrupted ? std::nullopt : mean_traversal_cost(world, camera);
        const IntersectionRun run{show, options, build_time.count(), settings.threads};
        return ChapterRun{result, intersection_notes(context.scene, world, run, result, cost), std::nullopt};
    };
    return run_chapter(argc, argv, chapter, flags, render);
}
