#include "world.hpp"

#include <algorithm>
#include <type_traits>
#include <variant>

#include "box.hpp"
#include "float_error.hpp"
#include "huge_pages.hpp"

namespace rt {

World::World(const Scene& scene, WorldOptions options) : options_(options) {
    for (const Shape& shape : scene.shapes) {
        const Material& m = scene.material_of(shape);
        add(shape, m.emissive(), !m.textures.empty());
    }
    if (!corners_.empty()) corners_.resize(triangle_count_);
    bounded_count_ = std::uint32_t(primitives_.size());
    if (options_.acceleration != Acceleration::kNone) {
        if (!quads_.empty()) pack_quads();
        // The wide tree's leaves are tested a packet of four triangles at a time: the SAH then weighs a leaf
        // by its packets (a leaf of spheres or quad packets as well, an approximation: those are tested one
        // by one).
        const bool packets = options_.acceleration == Acceleration::kBvh &&
                             options_.triangle_test == TriangleTest::kWatertight &&
                             options_.triangle_packets && options_.packet_sah;
        std::vector<std::uint32_t> order;
        bvh_ = Bvh(std::uint32_t(primitives_.size()), slot_bounds(), order,
                   packets ? std::uint32_t(kTriangleLanes) : 1);
        lay_out_in(order);
        if (options_.acceleration == Acceleration::kBvh) collapse_to_wide();
    }
    // A tree of one leaf is searched as a list, triangle by triangle (World::search): it keeps a copy.
    if (!triangle_sources_.empty() && bvh_.nodes().size() <= 1) {
        for (std::uint32_t i = 0; i < triangle_count_; ++i) triangles_.push_back(triangle_at(i));
    }
    triangle_sources_ = std::vector<TriangleSource>();
}

bool World::packs_triangles() const {
    return options_.acceleration == Acceleration::kBvh &&
           options_.triangle_test == TriangleTest::kWatertight && options_.triangle_packets;
}

// The wide BVH over the binary one. Each binary leaf becomes a list of items: its triangles four at a time
// in packets (watertight test only: the packet is its SIMD form), in leaf order, then its other primitives.
// A leaf of triangles only points at its packets directly: a ray reaching it loads them, and no list first.
// The packets are made first, leaf after leaf in slot order, then the wide nodes.
void World::collapse_to_wide() {
    const bool pack = packs_triangles();
    std::vector<Triangle> triangles;  // a leaf's, reused from leaf to leaf: no allocation per leaf
    std::vector<std::uint32_t> slots;
    auto items_of = [&](const BvhNode& leaf) {
        const std::uint32_t first_packet = std::uint32_t(triangle_packets_.size());
        triangles.clear();
        slots.clear();
        for (std::uint32_t slot = leaf.offset; slot < leaf.offset + leaf.count; ++slot) {
            if (pack && primitives_[slot].kind == Kind::kTriangle) {
                triangles.push_back(triangle_at(primitives_[slot].index));
                slots.push_back(slot);
            }
        }
        for (std::size_t at = 0; at < triangles.size(); at += kTriangleLanes) {
            const std::size_t n = std::min<std::size_t>(kTriangleLanes, triangles.size() - at);
            triangle_packets_.push_back(make_triangle_packet(std::span(triangles).subspan(at, n),
                                                             std::span(slots).subspan(at, n)));
        }
        const std::uint32_t packets = std::uint32_t(triangle_packets_.size()) - first_packet;
        if (triangles.size() == leaf.count) return WideBvh::ItemRange{kPacketItem | first_packet, packets};
        const std::uint32_t first = std::uint32_t(leaf_items_.size());
        for (std::uint32_t p = 0; p < packets; ++p) leaf_items_.push_back(kPacketItem | (first_packet + p));
        for (std::uint32_t slot = leaf.offset; slot < leaf.offset + leaf.count; ++slot) {
            if (!(pack && primitives_[slot].kind == Kind::kTriangle)) leaf_items_.push_back(slot);
        }
        return WideBvh::ItemRange{first, std::uint32_t(leaf_items_.size()) - first};
    };
    // The binary tree is depth first, so its leaves come in the order of their first slots.
    std::vector<std::uint32_t> leaf_first_slot;
    std::vector<WideBvh::ItemRange> leaf_items;
    // At most one packet per leaf more than a packet per four triangles: reserved at once, not grown.
    std::size_t leaves = 0;
    for (const BvhNode& node : bvh_.nodes()) leaves += node.leaf();
    if (pack) reserve_on_huge_pages(triangle_packets_, triangle_count_ / kTriangleLanes + leaves);
    leaf_first_slot.reserve(leaves);
    leaf_items.reserve(leaves);
    for (const BvhNode& node : bvh_.nodes()) {
        if (!node.leaf()) continue;
        leaf_first_slot.push_back(node.offset);
        leaf_items.push_back(items_of(node));
    }
    wide_ = WideBvh(bvh_, [&](const BvhNode& leaf) {
        const auto at = std::lower_bound(leaf_first_slot.begin(), leaf_first_slot.end(), leaf.offset);
        return leaf_items[std::size_t(at - leaf_first_slot.begin())];
    });
}

std::size_t World::acceleration_bytes() const {
    return bvh_.bytes() + wide_.bytes() + triangle_packets_.size() * sizeof(TrianglePacket) +
           leaf_items_.size() * sizeof(std::uint32_t);
}

std::function<Aabb(std::uint32_t)> World::slot_bounds() const {
    return [this](std::uint32_t slot) { return bounds(primitives_[slot]); };
}

// Replaces the quads by packets of four neighbours. A first BVH over every primitive lists them leaf by leaf,
// so neighbours come one after another; its quads, taken four at a time in that order, become the packets.
void World::pack_quads() {
    std::vector<std::uint32_t> order;
    const Bvh neighbours(std::uint32_t(primitives_.size()), slot_bounds(), order);
    quad_primitives_.resize(quads_.size());
    std::vector<Primitive> items;
    std::vector<std::uint32_t> quads_in_order;
    for (std::uint32_t slot : order) {
        const Primitive& p = primitives_[slot];
        if (p.kind == Kind::kQuad) {
            quad_primitives_[p.index] = p;
            quads_in_order.push_back(p.index);
        } else {
            items.push_back(p);
        }
    }
    for (std::size_t first = 0; first < quads_in_order.size(); first += kQuadLanes) {
        const std::size_t count = std::min<std::size_t>(kQuadLanes, quads_in_order.size() - first);
        items.push_back({Kind::kQuadPacket, false, std::uint32_t(packets_.size()), -1, 0, -1});
        packets_.push_back(make_quad_packet(quads_, std::span(quads_in_order).subspan(first, count)));
    }
    primitives_ = std::move(items);
}

void World::add_primitive(Kind kind, std::uint32_t index, int material, bool emissive, bool textured) {
    primitives_.push_back(
        {kind, textured, index, material, std::uint32_t(primitives_.size()), emissive ? light_count_++ : -1});
}

// Stores the primitives, and the spheres, quads, triangles and packets they point to, in the BVH's leaf order
// (a packet's quads stay where they are: only the packet is tested). Triangles that go into packets stay in
// scene order too: they are read once more, into their packets, and a copy in leaf order would only double
// the memory they take while the tree is built.
void World::lay_out_in(const std::vector<std::uint32_t>& order) {
    const bool move_triangles = !packs_triangles();
    std::vector<Primitive> primitives;
    std::vector<Sphere> spheres;
    std::vector<Quad> quads;
    std::vector<Triangle> triangles;
    std::vector<TriangleCorners> corners;
    std::vector<QuadPacket> packets;
    reserve_on_huge_pages(primitives, order.size());
    spheres.reserve(spheres_.size());
    quads.reserve(quads_.size());
    if (move_triangles) reserve_on_huge_pages(triangles, triangles_.size());
    packets.reserve(packets_.size());
    auto move_to = [](auto& to, const auto& from, std::uint32_t index) {
        to.push_back(from[index]);
        return std::uint32_t(to.size() - 1);
    };
    for (std::uint32_t old_slot : order) {
        Primitive p = primitives_[old_slot];
        switch (p.kind) {
            case Kind::kSphere:
                p.index = move_to(spheres, spheres_, p.index);
                break;
            case Kind::kQuad:
                p.index = move_to(quads, quads_, p.index);
                break;
            case Kind::kTriangle:
                if (!move_triangles) break;
                if (!corners_.empty()) move_to(corners, corners_, p.index);
                p.index = move_to(triangles, triangles_, p.index);
                break;
            case Kind::kQuadPacket:
                p.index = move_to(packets, packets_, p.index);
                break;
        }
        primitives.push_back(p);
    }
    primitives_ = std::move(primitives);
    spheres_ = std::move(spheres);
    if (packets_.empty()) quads_ = std::move(quads);
    if (move_triangles) {
        triangles_ = std::move(triangles);
        corners_ = std::move(corners);
    }
    packets_ = std::move(packets);
}

void World::add(const Shape& shape, bool emissive, bool textured) {
    const int material = shape.material;
    std::visit(
        [&](const auto& g) {
            using T = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<T, SphereShape>) {
                add_primitive(Kind::kSphere, std::uint32_t(spheres_.size()), material, emissive, textured);
                spheres_.push_back({g.center, g.radius});
            } else if constexpr (std::is_same_v<T, QuadShape>) {
                add_primitive(Kind::kQuad, std::uint32_t(quads_.size()), material, emissive, textured);
                quads_.push_back(make_quad(g.origin, g.u, g.v));
            } else if constexpr (std::is_same_v<T, TriangleShape>) {
                add_primitive(Kind::kTriangle, std::uint32_t(triangle_count_), material, emissive, textured);
                take_triangles(shape, 1);
            } else if constexpr (std::is_same_v<T, PlaneShape>) {
                planes_.push_back({make_plane(g.point, g.normal), material});
            } else if constexpr (std::is_same_v<T, BoxShape>) {
                for (const Quad& face : box_faces(g)) {
                    add_primitive(Kind::kQuad, std::uint32_t(quads_.size()), material, emissive, textured);
                    quads_.push_back(face);
                }
            } else if constexpr (std::is_same_v<T, MeshShape>) {
                const bool has_uv = !g.texture_coordinates.empty();
                reserve_on_huge_pages(primitives_, primitives_.size() + g.triangles.size());
                for (std::size_t i = 0; i < g.triangles.size(); ++i) {
                    const std::uint32_t index = std::uint32_t(triangle_count_ + i);
                    if (g.smooth() || has_uv) {
                        corners_.resize(index);  // the triangles before it have none
                        TriangleCorners c{{}, {}, g.smooth(), has_uv};
                        for (std::size_t k = 0; k < 3; ++k) {
                            if (c.smooth) c.normals[k] = g.normals[g.normal_corners[i][k]];
                            if (has_uv)
                                c.texture_coordinates[k] = g.texture_coordinates[g.texture_corners[i][k]];
                        }
                        corners_.push_back(c);
                    }
                    add_primitive(Kind::kTriangle, index, material, emissive, textured);
                }
                take_triangles(shape, g.triangles.size());
            }
        },
        shape.geometry);
}

// Triangle i of a TriangleShape (i = 0) or a mesh. Each triangle copies its mesh's shared vertices bit for
// bit: the watertight test sees the same floats on both sides of every edge.
Triangle triangle_of(const Shape& shape, std::size_t i) {
    if (const auto* mesh = std::get_if<MeshShape>(&shape.geometry)) {
        const auto& corner = mesh->triangles[i];
        return {mesh->positions[corner[0]], mesh->positions[corner[1]], mesh->positions[corner[2]]};
    }
    const auto& g = std::get<TriangleShape>(shape.geometry);
    return {g.vertices[0], g.vertices[1], g.vertices[2]};
}

void World::take_triangles(const Shape& shape, std::size_t count) {
    if (packs_triangles()) {
        triangle_sources_.push_back({std::uint32_t(triangle_count_), &shape});
    } else {
        reserve_on_huge_pages(triangles_, triangles_.size() + count);
        for (std::size_t i = 0; i < count; ++i) triangles_.push_back(triangle_of(shape, i));
    }
    triangle_count_ += count;
}

Triangle World::triangle_at(std::uint32_t index) const {
    if (triangle_sources_.empty()) return triangles_[index];
    const auto after = std::upper_bound(triangle_sources_.begin(), triangle_sources_.end(), index,
                                        [](std::uint32_t i, const TriangleSource& s) { return i < s.first; });
    const TriangleSource& source = *(after - 1);
    return triangle_of(*source.shape, index - source.first);
}

Aabb bounds_of(const Sphere& s) {
    Aabb box;
    box.extend(s.center - Vec3{s.radius});
    box.extend(s.center + Vec3{s.radius});
    return box;
}

Aabb bounds_of(const Quad& q) {
    Aabb box;
    for (const Vec3& c : {q.origin, q.origin + q.u, q.origin + q.v, q.origin + q.u + q.v}) box.extend(c);
    return box;
}

Aabb bounds_of(const Triangle& t) {
    Aabb box;
    for (const Vec3& c : {t.p0, t.p1, t.p2}) box.extend(c);
    return box;
}

Aabb World::bounds(const Primitive& p) const {
    Aabb box;
    switch (p.kind) {
        case Kind::kSphere:
            box = bounds_of(spheres_[p.index]);
            break;
        case Kind::kQuad:
            box = bounds_of(quads_[p.index]);
            break;
        case Kind::kQuadPacket: {
            const QuadPacket& packet = packets_[p.index];
            for (int lane = 0; lane < packet.lanes; ++lane)
                box.extend(bounds_of(quads_[packet.quad[std::size_t(lane)]]));
            break;
        }
        case Kind::kTriangle:
            box = bounds_of(triangle_at(p.index));
            break;
    }
    return box;
}

bool World::test(const Ray& ray, const WatertightRay& sheared, std::uint32_t slot, Real t_max,
                 Candidate& found) const {
    const Primitive& p = primitives_[slot];
    switch (p.kind) {
        case Kind::kSphere:
            if (const auto t = intersect_sphere(ray, spheres_[p.index], t_max)) {
                found = {*t, slot, Vec2{0}};
                return true;
            }
            return false;
        case Kind::kQuad:
            if (const auto h = intersect_quad(ray, quads_[p.index], t_max)) {
                found = {h->t, slot, h->ab};
                return true;
            }
            return false;
        case Kind::kQuadPacket:
            if (const auto h = intersect_quad_packet(ray, packets_[p.index], t_max)) {
                found = {h->hit.t, slot, h->hit.ab, h->lane};
                return true;
            }
            return false;
        case Kind::kTriangle: {
            const Triangle& tri = triangles_[p.index];
            const auto h = options_.triangle_test == TriangleTest::kWatertight
                               ? intersect_triangle_watertight(ray, sheared, tri, t_max)
                               : intersect_triangle_moller(ray, tri, t_max);
            if (h) {
                found = {h->t, slot, h->barycentrics};
                return true;
            }
            return false;
        }
    }
    return false;
}

// The items of a wide leaf, in order: a triangle packet at once, any other primitive alone.
bool World::test_items(const Ray& ray, const WatertightRay& sheared, const PacketRay& packet_ray,
                       std::uint32_t first, std::uint32_t count, Real& t_max, bool any_hit, Candidate& found) const {
    bool hit = false;
    auto test_packet = [&](std::uint32_t index) {
        const TrianglePacket& packet = triangle_packets_[index];
        const auto h = intersect_triangle_packet(packet_ray, packet, t_max);
        if (!h) return false;
        found = {h->hit.t, packet.slot[std::size_t(h->lane)], h->hit.barycentrics, h->lane, &packet};
        // The hit record will need the primitive's record: asked for now, it arrives while the walk goes on.
        __builtin_prefetch(&primitives_[found.slot]);
        return true;
    };
    if (first & kPacketItem) {  // a leaf of triangles: its packets
        const std::uint32_t first_packet = first & ~kPacketItem;
        for (std::uint32_t i = first_packet; i < first_packet + count; ++i) {
            if (!test_packet(i)) continue;
            t_max = found.t;
            hit = true;
            if (any_hit) return true;
        }
        return hit;
    }
    for (std::uint32_t i = first; i < first + count; ++i) {
        const std::uint32_t item = leaf_items_[i];
        if (item & kPacketItem) {
            if (!test_packet(item & ~kPacketItem)) continue;
        } else if (!test(ray, sheared, item, t_max, found)) {
            continue;
        }
        t_max = found.t;
        hit = true;
        if (any_hit) return true;
    }
    return hit;
}

bool World::search(const Ray& ray, Real t_max, bool any_hit, Candidate& found, TraversalStats* stats) const {
    bool hit = false;
    const std::uint32_t slots = std::uint32_t(primitives_.size());
    for (std::uint32_t i = 0; i < planes_.size(); ++i) {
        if (const auto t = intersect_plane(ray, planes_[i].plane, t_max)) {
            found = {*t, slots + i, Vec2{0}};
            t_max = *t;
            hit = true;
            if (any_hit) return true;
        }
    }
    // The watertight test's per-ray shear, computed only when there are triangles to test.
    const WatertightRay sheared = triangle_count_ == 0 ? WatertightRay{} : make_watertight_ray(ray);
    auto test_one = [&](std::uint32_t slot, Real& limit) {
        if (!test(ray, sheared, slot, limit, found)) return false;
        limit = found.t;
        return true;
    };
    // A BVH of one leaf (a small scene, like the Cornell box once its quads are packed) is a list: its box
    // would only turn away the rays that miss the whole scene, at the price of three divisions and a slab
    // test each.
    if (options_.acceleration == Acceleration::kBvh && bvh_.nodes().size() > 1) {
        const PacketRay packet_ray = make_packet_ray(ray, sheared);
        auto test_leaf = [&](std::uint32_t first, std::uint32_t count, Real& limit) {
            return test_items(ray, sheared, packet_ray, first, count, limit, any_hit, found);
        };
        return wide_.traverse(make_wide_ray(ray), t_max, any_hit, test_leaf, stats) || hit;
    }
    if (options_.acceleration == Acceleration::kBinaryBvh && bvh_.nodes().size() > 1) {
        return bvh_.traverse(ray, inverse_direction(ray.direction), t_max, any_hit, test_one, stats) || hit;
    }
    for (std::uint32_t i = 0; i < slots; ++i) {
        if (stats) ++stats->primitives;
        if (test_one(i, t_max)) {
            hit = true;
            if (any_hit) return true;
        }
    }
    return hit;
}

const World::Primitive& World::record_of(const Candidate& found) const {
    const Primitive& p = primitives_[found.slot];
    if (p.kind != Kind::kQuadPacket) return p;
    return quad_primitives_[packets_[p.index].quad[std::size_t(found.lane)]];
}

std::uint32_t World::number_of(const Candidate& found) const {
    const std::uint32_t slots = std::uint32_t(primitives_.size());
    return found.slot >= slots ? bounded_count_ + (found.slot - slots) : record_of(found).id;
}

Hit World::make_hit(const Ray& ray, const Candidate& found) const {
    Hit hit;
    hit.t = found.t;
    const std::uint32_t slots = std::uint32_t(primitives_.size());
    if (found.slot >= slots) {
        hit.primitive = number_of(found);
        const MaterialPlane& p = planes_[found.slot - slots];
        // Rebuilt from the plane's own coordinates, p = p0 + a T + b B: in the plane up to rounding.
        const Vec2 uv = plane_uv(p.plane, ray.at(found.t));
        const Vec3 along_t = uv.x * p.plane.tangent, along_b = uv.y * p.plane.bitangent;
        hit.point = p.plane.point + along_t + along_b;
        hit.point_error = gamma_bound(5) * (abs(p.plane.point) + abs(along_t) + abs(along_b));
        hit.material = p.material;
        const bool far = std::max({std::abs(ray.origin.x), std::abs(ray.origin.y), std::abs(ray.origin.z)}) >
                         kFarFromOrigin;
        hit.uv = far ? plane_texture_uv(p.plane, ray, found.t) : Vec2d(uv);
        set_face_normal(hit, ray.direction, p.plane.normal);
        return hit;
    }
    const Primitive& p = record_of(found);
    hit.primitive = p.id;
    hit.material = p.material;
    hit.light = p.light;
    switch (p.kind) {
        case Kind::kSphere: {
            const Sphere& s = spheres_[p.index];
            // Reprojected onto the sphere, p = c + r (p − c) / |p − c|: only the radial rounding remains.
            const Vec3 n = sphere_normal(s, ray.at(found.t));
            const Vec3 radial = s.radius * n;
            hit.point = s.center + radial;
            hit.point_error = gamma_bound(5) * (abs(s.center) + abs(radial));
            if (p.textured) hit.uv = sphere_uv(n);
            set_face_normal(hit, ray.direction, n);
            break;
        }
        case Kind::kQuad: {
            const Quad& q = quads_[p.index];
            const Vec3 along_u = found.uv.x * q.u, along_v = found.uv.y * q.v;
            hit.point = q.origin + along_u + along_v;
            hit.point_error = gamma_bound(3) * (abs(q.origin) + abs(along_u) + abs(along_v));
            hit.uv = found.uv;
            set_face_normal(hit, ray.direction, q.normal);
            break;
        }
        case Kind::kTriangle: {
            const Triangle t =
                found.triangles ? triangle_in(*found.triangles, found.lane) : triangles_[p.index];
            const Real b1 = found.uv.x, b2 = found.uv.y;
            const Vec3 w0 = (1 - b1 - b2) * t.p0, w1 = b1 * t.p1, w2 = b2 * t.p2;
            hit.point = w0 + w1 + w2;
            hit.point_error = gamma_bound(7) * (abs(w0) + abs(w1) + abs(w2));
            set_face_normal(hit, ray.direction, triangle_normal(t));
            hit.uv = found.uv;
            if (!corners_.empty()) interpolate_corners(hit, ray, corners_[p.index], b1, b2);
            break;
        }
        case Kind::kQuadPacket:
            break;  // resolved to its quad above
    }
    return hit;
}

// Phong's interpolation: n = b0 n0 + b1 n1 + b2 n2, normalised, then made a shading normal by the one fix
// (shading_normal.hpp); a normal that cancels out (opposite corners) leaves the geometric one.
void World::interpolate_corners(Hit& hit, const Ray& ray, const TriangleCorners& corners, Real b1,
                                Real b2) const {
    const Real b0 = 1 - b1 - b2;
    if (corners.textured) {
        const auto& uv = corners.texture_coordinates;
        hit.uv = b0 * uv[0] + b1 * uv[1] + b2 * uv[2];
    }
    if (!corners.smooth || options_.shading_normals == ShadingNormalFix::kFlat) return;
    const Vec3 n = b0 * corners.normals[0] + b1 * corners.normals[1] + b2 * corners.normals[2];
    const Real length = glm::length(n);
    if (!(length > Real(1e-6))) return;
    hit.shading_normal = shading_normal(n / length, hit.normal, -ray.direction, options_.shading_normals);
}

std::optional<Hit> World::intersect(const Ray& ray, Real t_max) const {
    Candidate found{};
    if (!search(ray, t_max, false, found, nullptr)) return std::nullopt;
    return make_hit(ray, found);
}

std::optional<Hit> World::intersect(const Ray& ray, Real t_max, TraversalStats& stats) const {
    Candidate found{};
    if (!search(ray, t_max, false, found, &stats)) return std::nullopt;
    return make_hit(ray, found);
}

std::optional<NearestHit> World::nearest(const Ray& ray, Real t_max) const {
    Candidate found{};
    if (!search(ray, t_max, false, found, nullptr)) return std::nullopt;
    return NearestHit{found.t, number_of(found), found.uv};
}

bool World::occluded(const Ray& ray, Real t_max) const {
    Candidate found{};
    return search(ray, t_max, true, found, nullptr);
}

std::size_t World::primitive_count() const {
    return bounded_count_ + planes_.size();
}

}  // namespace rt
