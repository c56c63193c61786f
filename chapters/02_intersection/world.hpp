// The world: every shape of a Scene as intersectable primitives — spheres, quads (a box becomes 6 quads,
// transformed), triangles (a mesh becomes its triangles) — in a BVH, and unbounded planes tested outside it.
// The nearest intersection is the smallest t in (0, t_max) over all primitives. With the BVH, neighbouring
// quads are grouped four by four into packets (quad_packet.hpp), each one leaf entry tested at once. The
// binary BVH is then collapsed into a 4-wide one (wide_bvh.hpp), which rays are traced through, and the
// triangles of each leaf are tested four at a time (triangle_packet.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "bvh.hpp"
#include "hit.hpp"
#include "plane.hpp"
#include "quad.hpp"
#include "quad_packet.hpp"
#include "rt/core/ray.hpp"
#include "rt/core/scene.hpp"
#include "shading_normal.hpp"
#include "sphere.hpp"
#include "triangle.hpp"
#include "triangle_packet.hpp"
#include "wide_bvh.hpp"

namespace rt {

// kBvh: the binary BVH collapsed into the wide one, traced through that (the default); kBinaryBvh: traced
// through the binary BVH itself, one triangle at a time (Bvh::traverse, the chapter's first exercise);
// kNone: every primitive tested.
enum class Acceleration { kBvh, kBinaryBvh, kNone };

constexpr auto names_of(Acceleration) {
    return enum_names<Acceleration>(
        "--accel", {{Acceleration::kBvh, "bvh"}, {Acceleration::kBinaryBvh, "binary"}, {Acceleration::kNone, "none"}});
}

struct WorldOptions {
    TriangleTest triangle_test = TriangleTest::kWatertight;
    Acceleration acceleration = Acceleration::kBvh;
    // With kBvh and the watertight test: each leaf's triangles are tested four at a time (false: one by one,
    // to measure what the packets buy).
    bool triangle_packets = true;
    // With triangle packets: the SAH weighs a leaf by the packets it tests, ⌈n / 4⌉, not by its n triangles
    // (false: by its triangles, to measure what that buys).
    bool packet_sah = true;
    // A smooth mesh's shading normals (shading_normal.hpp): kFlat (faceted) where the run does not simulate
    // them (chapters 02 and 03), kBend from chapter 04 on.
    ShadingNormalFix shading_normals = ShadingNormalFix::kFlat;
};

// The options of a render that simulates `simulated`: a smooth mesh's shading normals made by `fix` when it
// simulates them (chapter 04 on), the mesh faceted when not.
inline WorldOptions world_options_for(const EffectSet& simulated,
                                      ShadingNormalFix fix = ShadingNormalFix::kBend) {
    WorldOptions options;
    if (simulated.contains(Effect::kShadingNormals)) options.shading_normals = fix;
    return options;
}

// The box around a bounded primitive, as the BVH is built over (chapter 11 builds one over its own copy).
Aabb bounds_of(const Sphere& sphere);
Aabb bounds_of(const Quad& quad);
Aabb bounds_of(const Triangle& triangle);

class World {
  public:
    explicit World(const Scene& scene, WorldOptions options = {});

    // The nearest hit with 0 < t < t_max, if any, and its hit record. No offset is applied: spawning rays is
    // chapter 03's topic.
    std::optional<Hit> intersect(const Ray& ray, Real t_max = kInfinity) const;
    // The same, counting the boxes and primitives tested into `stats`.
    std::optional<Hit> intersect(const Ray& ray, Real t_max, TraversalStats& stats) const;
    // The same search, and only what it finds: the distance, the primitive and where on it (no hit record:
    // no point, normal, material or light to look up). What Embree's rtcIntersect1 reports, and what a query
    // that needs no shading asks (the leak probe: does the ray hit?).
    std::optional<NearestHit> nearest(const Ray& ray, Real t_max = kInfinity) const;
    // Whether anything is hit with 0 < t < t_max (any-hit: stops at the first hit found).
    bool occluded(const Ray& ray, Real t_max) const;

    // Spheres, quads, triangles and planes (a packet counts as the quads it holds).
    std::size_t primitive_count() const;
    // The binary hierarchy, as built (empty with Acceleration::kNone).
    const Bvh& bvh() const { return bvh_; }
    // The wide one the rays are traced through (empty unless Acceleration::kBvh).
    const WideBvh& wide_bvh() const { return wide_; }
    // The memory the acceleration adds to the primitives: the nodes of both trees, the triangle packets and
    // the wide leaves' item lists.
    std::size_t acceleration_bytes() const;
    std::size_t triangle_count() const { return triangle_count_; }

  private:
    enum class Kind : std::uint8_t { kSphere, kQuad, kTriangle, kQuadPacket };
    // A bounded primitive: which array holds it, whether its material has a texture, where, its material, its
    // number in scene order (what Hit::primitive reports, whatever order the BVH lays the primitives out in)
    // and the light it is (Hit::light). A packet's material, number and light are its quads' own, in
    // quad_primitives_. All that a hit record needs but the geometry is here, in one record in the BVH's leaf
    // order: one cache miss.
    struct Primitive {
        Kind kind;
        bool textured;  // its material has a texture: a sphere's hit record computes its uv
        std::uint32_t index;
        int material;
        std::uint32_t id;
        std::int32_t light;
    };
    struct MaterialPlane {
        Plane plane;
        int material;
    };
    // A mesh triangle's vertex normals and texture coordinates, where its file gives them.
    struct TriangleCorners {
        std::array<Vec3, 3> normals{};
        std::array<Vec2, 3> texture_coordinates{};
        bool smooth = false;
        bool textured = false;
    };
    // The nearest hit found so far, before its hit record is made: `slot` is the primitive's place in
    // primitives_, or primitives_.size() + i for plane i; `lane` is the quad's lane when the slot is a
    // packet. A triangle found in a triangle packet keeps the packet (`triangles`, and its lane): the hit
    // record reads the triangle's corners there, already in the cache, not from triangles_.
    struct Candidate {
        Real t;
        std::uint32_t slot;
        Vec2 uv;
        int lane = 0;
        const TrianglePacket* triangles = nullptr;
    };

    // Adds the primitives of `shape`; `emissive`: its material emits, so each bounded primitive is a light.
    void add(const Shape& shape, bool emissive, bool textured);
    void add_primitive(Kind kind, std::uint32_t index, int material, bool emissive, bool textured);
    void pack_quads();
    void lay_out_in(const std::vector<std::uint32_t>& order);
    void collapse_to_wide();
    // Whether the wide tree's leaves test every triangle in packets of four.
    bool packs_triangles() const;
    // Counts `count` triangles of `shape` in: copied into triangles_, or, when they will be packed, noted
    // in triangle_sources_.
    void take_triangles(const Shape& shape, std::size_t count);
    // Triangle `index` (in scene order), from triangles_ or, while a packed World is built, its shape.
    Triangle triangle_at(std::uint32_t index) const;
    // The box of the primitive in each slot, for the BVH's build.
    std::function<Aabb(std::uint32_t)> slot_bounds() const;
    Aabb bounds(const Primitive& p) const;
    bool test(const Ray& ray, const WatertightRay& sheared, std::uint32_t slot, Real t_max,
              Candidate& found) const;
    bool test_items(const Ray& ray, const WatertightRay& sheared, const PacketRay& packet_ray, std::uint32_t first,
                    std::uint32_t count, Real& t_max, bool any_hit, Candidate& found) const;
    bool search(const Ray& ray, Real t_max, bool any_hit, Candidate& found, TraversalStats* stats) const;
    // The record of the bounded primitive found (a quad of a packet: the quad's own).
    const Primitive& record_of(const Candidate& found) const;
    // Its number, Hit::primitive: the record's, or after the bounded ones for a plane.
    std::uint32_t number_of(const Candidate& found) const;
    Hit make_hit(const Ray& ray, const Candidate& found) const;
    // Interpolates a mesh triangle's corners at the barycentrics (b1, b2) into the hit's shading normal and
    // uv.
    void interpolate_corners(Hit& hit, const Ray& ray, const TriangleCorners& corners, Real b1,
                             Real b2) const;

    WorldOptions options_;
    std::vector<Sphere> spheres_;
    std::vector<Quad> quads_;
    // The triangles in scene order, tested one by one; empty when the wide tree's packets hold them all
    // (packs_triangles()) and the tree is more than one leaf.
    std::vector<Triangle> triangles_;
    std::size_t triangle_count_ = 0;
    // Where a packed World's triangles come from while it is built, the first of each shape's: the bounds
    // and the packets read them in the scene's shapes, and no copy of them is made.
    struct TriangleSource {
        std::uint32_t first;
        const Shape* shape;
    };
    std::vector<TriangleSource> triangle_sources_;
    // triangle i's corners, when some mesh has normals or texture coordinates (else empty: no cost).
    std::vector<TriangleCorners> corners_;
    std::vector<QuadPacket> packets_;
    std::vector<Primitive> quad_primitives_;        // with packets: quad i's own record (material, number)
    std::vector<Primitive> primitives_;             // the bounded ones; planes are numbered after them
    std::int32_t light_count_ = 0;                  // emissive bounded primitives so far
    std::uint32_t bounded_count_ = 0;               // spheres, quads and triangles
    std::vector<MaterialPlane> planes_;
    Bvh bvh_;
    // A wide leaf's items: a leaf of triangles only (every leaf of a mesh) is `kPacketItem | p` and a count,
    // its packets p, p + 1, … themselves; any other leaf lists its items in leaf_items_, each a primitive's
    // slot or kPacketItem | i for triangle packet i.
    static constexpr std::uint32_t kPacketItem = 1u << 31;
    std::vector<std::uint32_t> leaf_items_;
    std::vector<TrianglePacket> triangle_packets_;  // in leaf order: a leaf's packets are neighbours
    WideBvh wide_;
};

}  // namespace rt
