// What a BVH buys, measured: rays per second of nearest-hit and any-hit queries, brute force against the BVH,
// for generated meshes of 10^3 .. 10^6 triangles, on one thread and on every core; the BVH's build time and
// bytes per triangle; and what the watertight triangle test costs against Möller–Trumbore. Two sets of rays:
// camera rays (a 512×512 pinhole view of the mesh, coherent, like the chapter's render) and random rays (from
// random points around the mesh to random points inside it: incoherent, every query a new path through the
// tree and through memory). Each figure is the median of `--repeats` runs. It checks the lesson's three
// targets.
//
// `--embree` instead traces identical rays through the course's BVH, step by step (the binary BVH; the wide
// one, triangles one by one; the wide one with triangle packets, over a tree whose SAH counts triangles and
// over one whose SAH counts packets), and through Embree 3 (default and robust),
// on 1 and 2 threads, each figure the median of runs taken in turn (each run long enough that a wait for a
// core is a small part of it), and counts the rays each lets escape from
// the closed mesh. Both sides answer the same query: a nearest hit's distance, primitive and barycentrics
// (World::nearest, rtcIntersect1), or whether anything is hit (World::occluded, rtcOccluded1); a last column
// times the default World's nearest hits with their hit records (World::intersect), what a renderer asks. On
// one thread it also gives the ratio of the two engines' CPU times (the thread's own, which other jobs on the
// machine do not lengthen). `--embree --walk-bound` times the walk alone, told each ray's hit distance and
// with its leaves free: the most a faster triangle test could buy. Built with Embree only when CMake finds
// it; otherwise `--embree` says so and stops.
#include <sched.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "01_ray_generation/camera.hpp"
#include "leak_probe.hpp"
#include "mesh_generator.hpp"
#include "rt/core/median.hpp"
#include "rt/core/random.hpp"
#include "rt/run/strict_flags.hpp"
#include "world.hpp"
#ifdef RT_HAVE_EMBREE
#include "embree_mesh.hpp"
#endif

namespace {

using namespace rt;
using Clock = std::chrono::steady_clock;

// Seconds taken by `work`, the median of `repeats` runs.
double median_seconds(int repeats, const std::function<void()>& work) {
    std::vector<double> seconds;
    for (int i = 0; i < repeats; ++i) {
        const auto start = Clock::now();
        work();
        seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    return median(seconds);
}

// Rays from random points on a sphere of radius 3 around the mesh to random points within radius 1.2.
std::vector<Ray> make_random_rays(std::size_t count, std::uint64_t seed) {
    Pcg32 rng(seed, 1);
    auto in_ball = [&](Real radius) {
        while (true) {
            const Vec3 p = Vec3{rng.next_real(), rng.next_real(), rng.next_real()} * Real(2) - Real(1);
            if (glm::dot(p, p) <= 1 && glm::dot(p, p) > Real(1e-4)) return p * radius;
        }
    };
    std::vector<Ray> rays(count);
    for (Ray& ray : rays) {
        const Vec3 origin = glm::normalize(in_ball(1)) * Real(3);
        ray = {origin, glm::normalize(in_ball(Real(1.2)) - origin)};
    }
    return rays;
}

// The rays through the pixel centres of a side × side image of the unit sphere, seen from distance 3, row by
// row.
std::vector<Ray> make_camera_rays(int side) {
    const PinholeCamera camera = make_pinhole_camera({{0.3f, 0.5f, 3}, {0, 0, 0}, {0, 1, 0}, 45}, side, side);
    std::vector<Ray> rays;
    rays.reserve(std::size_t(side) * std::size_t(side));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            rays.push_back(camera_ray(camera, Real(x) + Real(0.5), Real(y) + Real(0.5)));
    return rays;
}

// The instruction set the course was compiled for (RT_ISA in CMakeLists.txt).
#ifdef __AVX2__
constexpr const char* kCompiledFor = "x86-64-v3 (AVX2)";
#else
constexpr const char* kCompiledFor = "x86-64 (SSE2)";
#endif

// The cores this process may run on (its affinity mask when first asked), in order.
const std::vector<int>& allowed_cores() {
    static const std::vector<int> cores = [] {
        std::vector<int> list;
        cpu_set_t set;
        if (sched_getaffinity(0, sizeof set, &set) == 0) {
            for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
                if (CPU_ISSET(cpu, &set)) list.push_back(cpu);
        }
        return list;
    }();
    return cores;
}

// The allowed core that worker 0 (the one of a one-thread measurement) is held on: --core.
int first_core = 0;

// The core worker t is held on: the allowed core first_core + t, counting round; -1 when none is known.
int core_of_worker(int worker) {
    const std::vector<int>& cores = allowed_cores();
    return cores.empty() ? -1 : cores[std::size_t(first_core + worker) % cores.size()];
}

// Holds the calling thread on one core while it lives (worker t on core_of_worker(t)), then lets it run
// where it could before. A figure and the one it is compared with are measured on the same core:
// the two cores of a virtual machine are not always alike, and the course's walk lost more on the slower one
// than Embree did (benchmark/README.md's "Which core").
class CoreHold {
  public:
    explicit CoreHold(int worker) {
        const int core = core_of_worker(worker);
        held_ = core >= 0 && sched_getaffinity(0, sizeof before_, &before_) == 0;
        if (!held_) return;
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(core, &one);
        held_ = sched_setaffinity(0, sizeof one, &one) == 0;
    }
    ~CoreHold() {
        if (held_) sched_setaffinity(0, sizeof before_, &before_);
    }
    CoreHold(const CoreHold&) = delete;
    CoreHold& operator=(const CoreHold&) = delete;

  private:
    cpu_set_t before_{};
    bool held_ = false;
};

// Traces every ray with `query(ray)` (true: a hit), split over `threads`, each worker held on its core;
// returns how many hit.
template <typename Query>
std::size_t count_hits(const std::vector<Ray>& rays, int threads, const Query& query) {
    std::vector<std::size_t> hits(std::size_t(threads), 0);
    auto work = [&](int t) {
        const CoreHold hold(t);
        std::size_t n = 0;
        for (std::size_t i = std::size_t(t); i < rays.size(); i += std::size_t(threads)) n += query(rays[i]) ? 1 : 0;
        hits[std::size_t(t)] = n;
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (auto& thread : pool) thread.join();
    std::size_t total = 0;
    for (std::size_t h : hits) total += h;
    return total;
}

// Traces every ray (nearest hit, or any hit), split over `threads`; returns how many hit.
std::size_t trace_all(const World& world, const std::vector<Ray>& rays, bool any_hit, int threads) {
    return count_hits(rays, threads, [&](const Ray& ray) {
        return any_hit ? world.occluded(ray, kInfinity) : world.intersect(ray).has_value();
    });
}

// Million rays per second over `rays`, the median of `repeats` runs.
double mrays_per_second(const World& world, const std::vector<Ray>& rays, bool any_hit, int threads,
                        int repeats) {
    const double seconds = median_seconds(repeats, [&] { trace_all(world, rays, any_hit, threads); });
    return double(rays.size()) / seconds * 1e-6;
}

// Boxes and primitives tested per ray, on average: what the tree saves, free of the machine's noise.
struct MeanTests {
    double boxes = 0;
    double primitives = 0;
};
MeanTests mean_tests(const World& world, const std::vector<Ray>& rays) {
    MeanTests mean;
    for (const Ray& ray : rays) {
        TraversalStats stats;
        world.intersect(ray, kInfinity, stats);
        mean.boxes += stats.nodes;
        mean.primitives += stats.primitives;
    }
    mean.boxes /= double(rays.size());
    mean.primitives /= double(rays.size());
    return mean;
}

Scene mesh_scene(MeshShape mesh) {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.shapes.push_back(Shape{std::move(mesh), 0, "mesh"});
    return scene;
}

#ifdef RT_HAVE_EMBREE
// The CPU time this thread has run for, in seconds (CLOCK_THREAD_CPUTIME_ID): on a machine shared with other
// jobs, what a one-thread measurement costs, without the time spent waiting for a core.
double thread_cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// Random unit directions and points in the ball of radius 0.5 around the origin, inside every mesh here
// (a unit sphere, radii jittered by 5 %).
struct InsideRays {
    std::vector<Ray> nearest;  // from a point inside, in a random direction: each must hit the mesh
    std::vector<Ray> shadow;   // from a point inside to a point at distance 3 outside: each is occluded
    std::vector<Real> shadow_t_max;
};
InsideRays make_inside_rays(std::size_t count, std::uint64_t seed) {
    Pcg32 rng(seed, 3);
    auto in_ball = [&](Real radius) {
        while (true) {
            const Vec3 p = Vec3{rng.next_real(), rng.next_real(), rng.next_real()} * Real(2) - Real(1);
            if (glm::dot(p, p) <= 1 && glm::dot(p, p) > Real(1e-4)) return p * radius;
        }
    };
    InsideRays rays;
    for (std::size_t i = 0; i < count; ++i) {
        rays.nearest.push_back({in_ball(Real(0.5)), glm::normalize(in_ball(1))});
        const Vec3 from = in_ball(Real(0.5)), to = glm::normalize(in_ball(1)) * Real(3);
        rays.shadow.push_back({from, glm::normalize(to - from)});
        rays.shadow_t_max.push_back(glm::length(to - from));
    }
    return rays;
}

// The course's four steps and Embree's two builds, traced on the same rays.
const WorldOptions kOptions[4] = {{TriangleTest::kWatertight, Acceleration::kBinaryBvh},
                                  {TriangleTest::kWatertight, Acceleration::kBvh, false},
                                  {TriangleTest::kWatertight, Acceleration::kBvh, true, false},
                                  {}};
struct Engines {
    World binary, wide_single, wide_triangle_sah, wide;
    EmbreeMesh embree, embree_robust;
    explicit Engines(const Scene& scene, const MeshShape& mesh)
        : binary(scene, kOptions[0]),
          wide_single(scene, kOptions[1]),
          wide_triangle_sah(scene, kOptions[2]),
          wide(scene, kOptions[3]),
          embree(mesh, false),
          embree_robust(mesh, true) {}
};
constexpr int kEngines = 6, kCourseEngines = 4;
// Timed beside the engines on nearest-hit rays: the default World's hit record too (World::intersect), where
// the engines report what Embree's rtcIntersect1 does (World::nearest).
constexpr int kWithHitRecord = kEngines, kTimed = kEngines + 1;
constexpr double kShortestRunSeconds = 0.2;
const char* const kEngineNames[kEngines] = {"binary BVH",
                                            "wide BVH, triangles 1 by 1",
                                            "wide BVH + packets, SAH counting triangles",
                                            "wide BVH + packets, SAH counting packets",
                                            "Embree",
                                            "Embree robust"};
const char* const kWithHitRecordName = "the last course column, with the hit record";

// How many of `rays` engine `e` finds a hit for (nearest hit, or any hit before t_max[i] when given); e ==
// kWithHitRecord: the default World's nearest hits with their hit records.
std::size_t trace_engine(const Engines& en, int e, const std::vector<Ray>& rays, const std::vector<Real>* t_max,
                         int threads) {
    const Real* limit = t_max ? t_max->data() : nullptr;
    auto index = [&](const Ray& r) { return std::size_t(&r - rays.data()); };
    auto world_query = [&](const World& w) {
        return [&, limit](const Ray& r) {
            return limit ? w.occluded(r, limit[index(r)]) : w.nearest(r).has_value();
        };
    };
    auto embree_query = [&](const EmbreeMesh& m) {
        return [&, limit](const Ray& r) {
            return limit ? m.occluded(r, limit[index(r)]) : m.intersect(r, kInfinity).has_value();
        };
    };
    switch (e) {
        case 0: return count_hits(rays, threads, world_query(en.binary));
        case 1: return count_hits(rays, threads, world_query(en.wide_single));
        case 2: return count_hits(rays, threads, world_query(en.wide_triangle_sah));
        case 3: return count_hits(rays, threads, world_query(en.wide));
        case 4: return count_hits(rays, threads, embree_query(en.embree));
        case kWithHitRecord:
            return count_hits(rays, threads, [&](const Ray& r) { return en.wide.intersect(r).has_value(); });
        default: return count_hits(rays, threads, embree_query(en.embree_robust));
    }
}

// One mesh's rows of the build and escape tables: per engine, its build time and bytes per triangle, and how
// many rays escaped the closed mesh (from inside, shadow rays, the leak probe).
struct EmbreeRow {
    double triangles, build_ms[kEngines], bytes[kEngines];
    std::size_t escaped[3][kEngines], probe_rays;
};

// The worst ratio of the course's Mrays/s to Embree's over the table, and of their CPU times on one thread.
struct WorstRatios {
    double rate = kInfinity, cpu = kInfinity;
};

// A set of rays the engines trace: nearest hits, or any hit before t_max when given.
struct RaySet {
    const char* name;
    const std::vector<Ray>* rays;
    const std::vector<Real>* t_max;
};

// What the comparison measures, and the head of its first table.
void print_embree_header(std::size_t camera_rays, int ray_count, int repeats) {
    std::printf(
        "Identical rays through the course's BVH and Embree %s, one ray at a time, on closed uv spheres of "
        "n triangles (radii jittered by 5%%): %zu camera rays (nearest hit), %d rays from inside (nearest hit), "
        "%d shadow rays from inside to outside (any hit). Nearest hits: distance, primitive and barycentrics "
        "on both sides (World::nearest, rtcIntersect1), and in the column after Embree's the default's hit "
        "record too (World::intersect). Mrays/s, the median of %d runs taken in turn (engine after engine, "
        "run after run), each run tracing the set as many times as Embree takes %.1f s for on one thread. "
        "The course compiled for %s. Every figure of a row measured on the same cores: one thread on core %d, "
        "two threads on it and the next.\n\n",
        embree_version(), camera_rays, ray_count, ray_count, repeats, kShortestRunSeconds, kCompiledFor,
        core_of_worker(0));
    std::printf("| triangles | rays | threads |");
    for (const char* name : kEngineNames) std::printf(" %s |", name);
    std::printf(" %s | course / Embree | course / Embree, thread CPU time |\n"
                "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
                kWithHitRecordName);
}

// Each engine's build time (the median of `repeats`, engine after engine, run after run) and bytes per
// triangle.
void measure_builds(EmbreeRow& row, const Scene& scene, const MeshShape& mesh, const Engines& engines,
                    int repeats) {
    std::vector<double> build[kEngines];
    for (int r = 0; r < repeats; ++r) {
        for (int e = 0; e < kCourseEngines; ++e)
            build[e].push_back(median_seconds(1, [&] { const World w(scene, kOptions[e]); }));
        build[4].push_back(median_seconds(1, [&] { const EmbreeMesh m(mesh, false); }));
        build[5].push_back(median_seconds(1, [&] { const EmbreeMesh m(mesh, true); }));
    }
    const World* worlds[kCourseEngines] = {&engines.binary, &engines.wide_single, &engines.wide_triangle_sah,
                                           &engines.wide};
    for (int e = 0; e < kEngines; ++e) {
        row.build_ms[e] = median(build[e]) * 1e3;
        const EmbreeMesh& embree = e == 4 ? engines.embree : engines.embree_robust;
        row.bytes[e] =
            double(e < kCourseEngines ? worlds[e]->acceleration_bytes() : embree.bytes()) / row.triangles;
    }
}

// How many rays from inside, shadow rays and leak-probe rays each engine lets escape the closed mesh.
void count_escapes(EmbreeRow& row, const Engines& engines, const InsideRays& inside, const MeshShape& mesh) {
    const std::vector<Ray> probe = leak_probe_rays(mesh);
    row.probe_rays = probe.size();
    for (int e = 0; e < kEngines; ++e) {
        row.escaped[0][e] = inside.nearest.size() - trace_engine(engines, e, inside.nearest, nullptr, 1);
        row.escaped[1][e] =
            inside.shadow.size() - trace_engine(engines, e, inside.shadow, &inside.shadow_t_max, 1);
        row.escaped[2][e] = probe.size() - trace_engine(engines, e, probe, nullptr, 1);
    }
}

// The rows of one ray set on one mesh, on 1 and 2 threads: every engine's Mrays/s, the course's over
// Embree's, and on one thread the ratio of their CPU times; the worst ratios kept in `worst`.
void time_ray_set(const Engines& engines, double triangles, const RaySet& set, int repeats,
                  WorstRatios& worst) {
    // Each timed run traces the set `passes` times, as many as Embree takes a fifth of a second for on
    // one thread: a set of a few milliseconds (small meshes) is as long as the slices a busy machine
    // gives a thread, and one wait for a core would change its time by a tenth or more.
    const double one_pass = median_seconds(3, [&] { trace_engine(engines, 4, *set.rays, set.t_max, 1); });
    const int passes = std::max(1, int(std::ceil(kShortestRunSeconds / one_pass)));
    for (int threads : {1, 2}) {
        // An any-hit query makes no hit record: its last column would time the default again.
        const int timed = set.t_max ? kEngines : kTimed;
        std::vector<double> seconds[kTimed], cpu_seconds[kTimed];
        for (int r = 0; r < repeats; ++r) {
            for (int e = 0; e < timed; ++e) {
                const double cpu_start = thread_cpu_seconds();
                seconds[e].push_back(median_seconds(1, [&] {
                    for (int pass = 0; pass < passes; ++pass)
                        trace_engine(engines, e, *set.rays, set.t_max, threads);
                }));
                cpu_seconds[e].push_back(thread_cpu_seconds() - cpu_start);
            }
        }
        std::printf("| %.0f | %s | %d |", triangles, set.name, threads);
        double rate[kTimed];
        for (int e = 0; e < timed; ++e) {
            rate[e] = double(set.rays->size()) * passes / median(seconds[e]) * 1e-6;
            std::printf(" %.2f |", rate[e]);
        }
        if (timed == kEngines) std::printf(" |");
        std::printf(" %.2f |", rate[3] / rate[4]);
        // With one thread, this thread did all the work: the ratio of its CPU times, which waiting
        // for a core does not change. (With two, the other thread's time is not in it.)
        if (threads == 1) {
            const double cpu_ratio = median(cpu_seconds[4]) / median(cpu_seconds[3]);
            std::printf(" %.2f |\n", cpu_ratio);
            worst.cpu = std::min(worst.cpu, cpu_ratio);
        } else {
            std::printf(" |\n");
        }
        std::fflush(stdout);
        worst.rate = std::min(worst.rate, rate[3] / rate[4]);
    }
}

// The table of build times and bytes per triangle.
void print_build_table(const std::vector<EmbreeRow>& rows, int repeats) {
    std::printf("\nBuild (ms, median of %d, in turn) and bytes per triangle (the course: its nodes, packets and leaf "
                "lists, beside its triangles and their records; Embree: all it allocated)\n\n| triangles |",
                repeats);
    for (const char* name : kEngineNames) std::printf(" %s: build ms, bytes/tri |", name);
    std::printf("\n|---:|---|---|---|---|---|---|\n");
    for (const EmbreeRow& row : rows) {
        std::printf("| %.0f |", row.triangles);
        for (int e = 0; e < kEngines; ++e) std::printf(" %.1f ms, %.1f B |", row.build_ms[e], row.bytes[e]);
        std::printf("\n");
    }
}

// The table of rays that escaped; true when none escaped the course's BVH.
bool print_escape_table(const std::vector<EmbreeRow>& rows, int ray_count) {
    std::printf("\nRays that escaped the closed mesh (from inside: %d nearest-hit and %d shadow rays; the leak "
                "probe's rays aimed from the centroid at every vertex and at 3 points of every edge)\n\n"
                "| triangles | rays |",
                ray_count, ray_count);
    for (const char* name : kEngineNames) std::printf(" %s |", name);
    std::printf("\n|---:|---|---:|---:|---:|---:|---:|---:|\n");
    bool watertight = true;
    for (const EmbreeRow& row : rows) {
        const char* names[3] = {"from inside", "shadow (any hit)", "leak probe"};
        for (int s = 0; s < 3; ++s) {
            std::printf("| %.0f | %s%s |", row.triangles, names[s],
                        s == 2 ? (" (" + std::to_string(row.probe_rays) + ")").c_str() : "");
            for (int e = 0; e < kEngines; ++e) std::printf(" %zu |", row.escaped[s][e]);
            std::printf("\n");
            for (int e = 0; e < kCourseEngines; ++e) watertight = watertight && row.escaped[s][e] == 0;
        }
    }
    return watertight;
}

// The goals against Embree: on every row at least this share of its rate, and from 10^5 triangles a build
// within this multiple of its time.
constexpr double kRateTarget = 0.85, kBuildTimeTarget = 2;

// The course's default build time over Embree's default, worst over the meshes of 10^5 triangles and more.
double worst_build_ratio(const std::vector<EmbreeRow>& rows) {
    double worst = 0;
    for (const EmbreeRow& row : rows) {
        if (row.triangles >= 9e4) worst = std::max(worst, row.build_ms[3] / row.build_ms[4]);
    }
    return worst;
}

int compare_with_embree(int repeats, int ray_count, int max_exponent, bool builds_only) {
    const std::vector<Ray> camera_rays = make_camera_rays(512);
    const InsideRays inside = make_inside_rays(std::size_t(ray_count), 11);
    print_embree_header(camera_rays.size(), ray_count, repeats);
    std::vector<EmbreeRow> rows;
    WorstRatios worst;
    for (int exponent = 3; exponent <= max_exponent; ++exponent) {
        const int segments = int(std::lround(std::sqrt(std::pow(10.0, exponent))));
        MeshShape mesh = make_uv_sphere(segments, segments / 2 + 1);
        jitter_radii(mesh, Real(0.05), 5);
        const Scene scene = mesh_scene(mesh);
        const Engines engines(scene, mesh);
        EmbreeRow row{};
        row.triangles = double(mesh.triangles.size());
        measure_builds(row, scene, mesh, engines, repeats);
        rows.push_back(row);
        if (builds_only) continue;
        count_escapes(rows.back(), engines, inside, mesh);
        const RaySet sets[3] = {{"camera", &camera_rays, nullptr},
                                {"from inside", &inside.nearest, nullptr},
                                {"shadow (any hit)", &inside.shadow, &inside.shadow_t_max}};
        for (const RaySet& set : sets) time_ray_set(engines, row.triangles, set, repeats, worst);
    }
    print_build_table(rows, repeats);
    const double build_ratio = worst_build_ratio(rows);
    if (max_exponent >= 5)
        std::printf(
            "\n  the course's build time / Embree's, worst from 10^5 triangles: %.2f (target <= %.0f): %s\n",
            build_ratio, kBuildTimeTarget, build_ratio <= kBuildTimeTarget ? "met" : "NOT MET");
    if (builds_only) return build_ratio <= kBuildTimeTarget ? 0 : 1;
    const bool watertight = print_escape_table(rows, ray_count);
    std::printf(
        "\nTargets:\n  the course's Mrays/s / Embree's, worst over the table: %.2f (target >= %.2f): %s\n",
        worst.rate, kRateTarget, worst.rate >= kRateTarget ? "met" : "NOT MET");
    std::printf("  (the same on one thread's CPU time, worst over the one-thread rows: %.2f)\n", worst.cpu);
    std::printf("  rays escaping the course's BVH: %s\n", watertight ? "none (met)" : "SOME (NOT MET)");
    return worst.rate >= kRateTarget && build_ratio <= kBuildTimeTarget && watertight ? 0 : 1;
}

// How fast the course could trace rays from inside if its leaves cost nothing. Told each ray's hit distance
// in advance, the walk visits only the boxes entered before the hit, the fewest any nearest-first walk
// visits, and its leaves are only counted: the rate no faster triangle test can exceed. Beside it, the same
// walk with its leaves tested, the whole query and Embree's; one thread, each run's CPU time, in turn.
int bound_the_walk(int repeats, int ray_count, int max_exponent) {
    const InsideRays inside = make_inside_rays(std::size_t(ray_count), 11);
    std::printf(
        "Rays from inside (%d, nearest hit), one thread on core %d, Mrays/s on the thread's CPU time, the "
        "median of %d runs in turn\n\n| triangles | the course | its walk alone, hit distance given, "
        "leaves free | the same walk, leaves tested | Embree | walk alone / Embree | leaves per ray |\n"
        "|---:|---:|---:|---:|---:|---:|---:|\n",
        ray_count, core_of_worker(0), repeats);
    double worst_bound = kInfinity;
    for (int exponent = 3; exponent <= max_exponent; ++exponent) {
        const int segments = int(std::lround(std::sqrt(std::pow(10.0, exponent))));
        MeshShape mesh = make_uv_sphere(segments, segments / 2 + 1);
        jitter_radii(mesh, Real(0.05), 5);
        const World world(mesh_scene(mesh));
        const EmbreeMesh embree(mesh, false);
        const std::vector<Ray>& rays = inside.nearest;
        std::vector<Real> hit_t;
        for (const Ray& ray : rays) hit_t.push_back(world.nearest(ray).value_or(NearestHit{}).t);
        std::size_t leaves = 0;  // counted, so that the walk alone is not optimised away
        auto course = [&](std::size_t i) { leaves += world.nearest(rays[i]).has_value(); };
        auto walk_alone = [&](std::size_t i) {
            Real t_max = hit_t[i];
            world.wide_bvh().traverse(make_wide_ray(rays[i]), t_max, false, [&](auto, auto, Real&) {
                ++leaves;
                return false;
            });
        };
        auto walk_and_leaves = [&](std::size_t i) {
            leaves += world.nearest(rays[i], std::nextafter(hit_t[i], kInfinity)).has_value();
        };
        auto embree_query = [&](std::size_t i) {
            leaves += embree.intersect(rays[i], kInfinity).has_value();
        };
        std::vector<double> cpu[4];
        auto time = [&](int q, auto&& query) {
            const double start = thread_cpu_seconds();
            int passes = 0;
            do {
                for (std::size_t i = 0; i < rays.size(); ++i) query(i);
                ++passes;
            } while (thread_cpu_seconds() - start < kShortestRunSeconds);
            cpu[q].push_back((thread_cpu_seconds() - start) / passes);
        };
        const CoreHold hold(0);
        for (int r = 0; r < repeats; ++r) {
            time(0, course);
            time(1, walk_alone);
            time(2, walk_and_leaves);
            time(3, embree_query);
        }
        leaves = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) walk_alone(i);
        double rate[4];
        for (int q = 0; q < 4; ++q) rate[q] = double(rays.size()) / median(cpu[q]) * 1e-6;
        std::printf("| %zu | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", mesh.triangles.size(), rate[0],
                    rate[1], rate[2], rate[3], rate[1] / rate[3], double(leaves) / double(rays.size()));
        std::fflush(stdout);
        worst_bound = std::min(worst_bound, rate[1] / rate[3]);
    }
    std::printf("\n  the walk alone / Embree, worst: %.2f: %s\n", worst_bound,
                worst_bound >= kRateTarget ? "a faster triangle test could reach the target on these rows"
                                           : "below the target before any triangle is tested");
    return 0;
}
#endif

// The figures of one mesh size that the targets are judged on.
struct SizeFigures {
    double triangles, build, bytes, all_bytes, camera_1, random_1;
};

// One row of the table, a uv sphere of about 10^exponent triangles: its build, bytes, and rays per second of
// each kind on 1 thread and on every core, brute force beside the BVH; printed, and written to `csv` if open.
SizeFigures measure_size(int exponent, const std::vector<Ray>& camera_rays,
                         const std::vector<Ray>& random_rays, int cores, int repeats, std::ofstream& csv) {
    // A uv sphere with s segments and s/2 + 1 rings has s² triangles.
    const int segments = int(std::lround(std::sqrt(std::pow(10.0, exponent))));
    const Scene scene = mesh_scene(make_uv_sphere(segments, segments / 2 + 1));
    const double triangles = double(segments) * double(segments);
    const double build = median_seconds(repeats, [&] { const World world(scene); });
    const World world(scene);
    const double bytes = double(world.bvh().bytes()) / triangles;
    const double all_bytes = double(world.acceleration_bytes()) / triangles;
    const double camera_1 = mrays_per_second(world, camera_rays, false, 1, repeats);
    const double camera_n = mrays_per_second(world, camera_rays, false, cores, repeats);
    const double random_1 = mrays_per_second(world, random_rays, false, 1, repeats);
    const double random_n = mrays_per_second(world, random_rays, false, cores, repeats);
    const double any_1 = mrays_per_second(world, random_rays, true, 1, repeats);
    const double any_n = mrays_per_second(world, random_rays, true, cores, repeats);
    // Brute force tests every triangle: about 2·10^7 triangle tests per measurement.
    const World brute(scene, {TriangleTest::kWatertight, Acceleration::kNone});
    const std::size_t brute_rays = std::max<std::size_t>(16, std::size_t(2e7 / triangles));
    const std::vector<Ray> few(
        random_rays.begin(), random_rays.begin() + std::ptrdiff_t(std::min(brute_rays, random_rays.size())));
    const double brute_1 = mrays_per_second(brute, few, false, 1, repeats);
    const double brute_n = mrays_per_second(brute, few, false, cores, repeats);
    const double brute_any_1 = mrays_per_second(brute, few, true, 1, repeats);
    const MeanTests tests = mean_tests(world, random_rays);
    std::printf(
        "| %.0f | %.1f | %.2f | %.1f | %.1f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.5f | %.5f | %.5f | "
        "%.0f× | "
        "%.1f + %.1f |\n",
        triangles, build * 1e3, build / triangles * 1e6, bytes, all_bytes, camera_1, camera_n, random_1, random_n,
        any_1, any_n, brute_1, brute_n, brute_any_1, random_1 / brute_1, tests.boxes, tests.primitives);
    std::fflush(stdout);
    if (csv) {
        csv << triangles << ',' << build * 1e3 << ',' << bytes << ',' << camera_1 << ',' << camera_n << ','
            << random_1 << ',' << random_n << ',' << any_1 << ',' << brute_1 << ',' << tests.boxes << ','
            << tests.primitives << ',' << any_n << ',' << brute_n << ',' << brute_any_1 << '\n';
    }
    return {triangles, build, bytes, all_bytes, camera_1, random_1};
}

// What the targets are judged on, over every size: the time per ray at the smallest and the largest, the
// slowest build per million triangles (from 10^5 on), the most bytes per triangle.
struct TargetFigures {
    double camera_smallest = 0, camera_largest = 0, random_smallest = 0, random_largest = 0;
    double worst_build_per_million = 0, worst_bytes = 0, worst_all_bytes = 0;

    void add(int exponent, const SizeFigures& f) {
        if (exponent == 3) {
            camera_smallest = 1 / f.camera_1;
            random_smallest = 1 / f.random_1;
        }
        camera_largest = 1 / f.camera_1;
        random_largest = 1 / f.random_1;
        // Builds of less than 10^5 triangles take a few milliseconds: too short to time on a busy machine.
        if (f.triangles >= 1e5)
            worst_build_per_million = std::max(worst_build_per_million, f.build / f.triangles * 1e6);
        worst_bytes = std::max(worst_bytes, f.bytes);
        worst_all_bytes = std::max(worst_all_bytes, f.all_bytes);
    }
};

// The cost of watertightness: the same BVH, the same rays, the two triangle tests.
void print_triangle_test_cost(const std::vector<Ray>& random_rays, int repeats) {
    const Scene scene = mesh_scene(make_uv_sphere(316, 159));
    const World watertight(scene, {TriangleTest::kWatertight, Acceleration::kBvh});
    const World moller(scene, {TriangleTest::kMollerTrumbore, Acceleration::kBvh});
    const double watertight_rate = mrays_per_second(watertight, random_rays, false, 1, repeats);
    const double moller_rate = mrays_per_second(moller, random_rays, false, 1, repeats);
    std::printf(
        "\nTriangle test on 99856 triangles, random rays, nearest hit, 1 thread: watertight %.2f Mrays/s, "
        "Möller–Trumbore %.2f Mrays/s: watertight takes %.2f× the time\n",
        watertight_rate, moller_rate, moller_rate / watertight_rate);
}

// Prints the lesson's three targets and whether each was met; the exit status: 0 when all were.
int print_targets(const TargetFigures& t, int max_exponent) {
    const double camera_growth = t.camera_largest / t.camera_smallest;
    const double random_growth = t.random_largest / t.random_smallest;
    // A target is judged only where it was measured: the growth target is set for 10^6 triangles, and build
    // times are timed from 10^5 triangles on. A smaller run says so rather than "met".
    const bool growth_measured = max_exponent >= 6, build_measured = max_exponent >= 5;
    const bool growth_ok = !growth_measured || camera_growth <= 3;
    const bool build_ok = !build_measured || t.worst_build_per_million < 1, bytes_ok = t.worst_bytes <= 64;
    auto verdict = [](bool measured, bool ok) { return !measured ? "not judged" : ok ? "met" : "NOT MET"; };
    std::printf("\nTargets:\n");
    std::printf("  time per camera ray at 10^%d triangles / at 10^3: %.2f (target <= 3 at 10^6): %s%s\n",
                max_exponent, camera_growth, verdict(growth_measured, growth_ok),
                growth_measured ? "" : " (run with --max-exponent 6 or more)");
    std::printf("  (random rays, for comparison: %.2f; they miss the caches at every level of the tree)\n",
                random_growth);
    if (build_measured) {
        std::printf("  build time per million triangles (10^5 and more), up to two threads: %.2f s (target < 1 s): %s\n",
                    t.worst_build_per_million, verdict(true, build_ok));
    } else {
        std::printf("  build time per million triangles (target < 1 s): not measured (builds are timed from 10^5 "
                    "triangles on: run with --max-exponent 5 or more)\n");
    }
    std::printf("  BVH bytes per triangle, the binary tree as built: %.1f (target <= 64): %s\n", t.worst_bytes,
                verdict(true, bytes_ok));
    std::printf("  (with the wide tree, the triangle packets and the leaf lists it is traced through: %.1f)\n",
                t.worst_all_bytes);
    return growth_ok && build_ok && bytes_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    int repeats = 5;
    int ray_count = 1 << 17;
    int max_exponent = 6;
    CLI::App app("Chapter 02 benchmark: BVH against brute force, 10^3 .. 10^6 triangles", "ch02_benchmark");
    app.option_defaults()->always_capture_default();  // --help shows each flag's default
    app.add_option("--repeats", repeats, "Runs per figure (the median is reported)")
        ->check(CLI::Range(1, 99));
    app.add_option("--rays", ray_count, "Random rays per measurement")->check(CLI::Range(1000, 1 << 24));
    app.add_option("--max-exponent", max_exponent, "Largest mesh: 10^N triangles")->check(CLI::Range(3, 7));
    std::string csv_path;
    app.add_option("--csv", csv_path, "Also write the table as CSV");
    app.add_option("--core", first_core,
                   "The allowed core (counted from 0 among those the process may use) a one-thread figure is "
                   "measured on; with two threads, it and the next")
        ->check(CLI::Range(0, CPU_SETSIZE - 1));
    bool embree = false;
    app.add_flag("--embree", embree,
                 "Instead: the course's BVH, step by step, against Embree 3 on identical rays (when built with it)");
    bool builds_only = false;
    app.add_flag("--builds-only", builds_only,
                 "With --embree: only the build table (times and bytes), no rays")
        ->needs("--embree");
    bool walk_bound = false;
    app.add_flag("--walk-bound", walk_bound,
                 "With --embree: rays from inside only, the walk alone (hit distance given, leaves free) "
                 "against Embree")
        ->needs("--embree")
        ->excludes("--builds-only");
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;
    if (embree) {
#ifdef RT_HAVE_EMBREE
        return walk_bound ? bound_the_walk(repeats, ray_count, max_exponent)
                          : compare_with_embree(repeats, ray_count, max_exponent, builds_only);
#else
        std::printf("ch02_benchmark --embree: skipped, built without Embree 3 (install libembree-dev and "
                    "configure again: CMake then finds it)\n");
        return 0;
#endif
    }
    std::ofstream csv;
    if (!csv_path.empty()) {
        csv.open(csv_path);
        if (!csv) {
            std::fprintf(stderr, "ch02_benchmark: --csv: %s: cannot be written\n", csv_path.c_str());
            return 2;
        }
        csv << "triangles,build_ms,bvh_bytes_per_triangle,camera_mrays_1,camera_mrays_all,random_mrays_1,"
               "random_mrays_all,random_anyhit_mrays_1,brute_mrays_1,boxes_per_ray,primitives_per_ray,"
               "random_anyhit_mrays_all,brute_mrays_all,brute_anyhit_mrays_1\n";
    }
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const std::vector<Ray> camera_rays = make_camera_rays(512);
    const std::vector<Ray> random_rays = make_random_rays(std::size_t(ray_count), 7);

    std::printf(
        "BVH against brute force on uv spheres of n triangles: %zu camera rays, %d random rays, median of %d "
        "runs, %d cores; Mrays/s of nearest-hit queries unless marked any-hit\n\n",
        camera_rays.size(), ray_count, repeats, cores);
    std::printf(
        "| triangles | build (ms) | build (s per 10^6) | BVH bytes/tri | with wide BVH and packets | camera, 1 thread | camera, %d "
        "threads | "
        "random, 1 thread | random, %d threads | random any-hit, 1 thread | random any-hit, %d threads | "
        "brute force, random, 1 thread | brute force, %d threads | brute force any-hit, 1 thread | "
        "BVH speed-up | boxes + primitives per random ray |\n",
        cores, cores, cores, cores);
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    TargetFigures targets;
    for (int exponent = 3; exponent <= max_exponent; ++exponent)
        targets.add(exponent, measure_size(exponent, camera_rays, random_rays, cores, repeats, csv));
    print_triangle_test_cost(random_rays, repeats);
    return print_targets(targets, max_exponent);
}
