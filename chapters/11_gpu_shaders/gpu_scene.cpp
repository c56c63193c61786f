#include "gpu_scene.hpp"

#include <cstdio>
#include <type_traits>
#include <typeindex>
#include <unordered_map>
#include <variant>

#include "02_intersection/box.hpp"
#include "02_intersection/plane.hpp"
#include "02_intersection/world.hpp"
#include "04_direct_lighting/brdf.hpp"
#include "04_direct_lighting/distant_emitter.hpp"
#include "04_direct_lighting/point_emitter.hpp"
#include "04_direct_lighting/quad_emitter.hpp"
#include "04_direct_lighting/sphere_emitter.hpp"
#include "04_direct_lighting/spot_emitter.hpp"
#include "04_direct_lighting/triangle_emitter.hpp"
#include "07_bsdf_refraction/conductor.hpp"
#include "07_bsdf_refraction/dielectric.hpp"
#include "07_bsdf_refraction/fresnel.hpp"
#include "07_bsdf_refraction/rough_dielectric.hpp"
#include "rt/core/errors.hpp"

namespace rt {
namespace {

GpuVec4 v4(const Vec3& v, Real w = 0) {
    return {float(v.x), float(v.y), float(v.z), float(w)};
}

// The primitives of the scene in scene order, each with its light: the k-th emissive bounded primitive is
// Hit::light k (chapter 02's numbering), which LightSet::by_hit maps to its place among the picker's lights.
class PrimitiveList {
  public:
    PrimitiveList(const LightSet& lights, const LightPicker& picker) : lights_(lights), picker_(picker) {}

    void add(GpuPrimitive p, const Aabb& box, bool emissive) {
        p.info.z = emissive ? light_of(next_light_++) : GpuPrimitive::kNoLight;
        p.info.w = std::uint32_t(bounded.size());
        bounded.push_back(p);
        bounds.push_back(box);
    }

    std::vector<GpuPrimitive> bounded;
    std::vector<Aabb> bounds;

  private:
    std::uint32_t light_of(std::size_t k) const {
        if (picker_.empty() || k >= lights_.by_hit.size() || lights_.by_hit[k] < 0)
            return GpuPrimitive::kNoLight;
        return std::uint32_t(lights_.by_hit[k]);
    }

    const LightSet& lights_;
    const LightPicker& picker_;
    std::size_t next_light_ = 0;
};

GpuPrimitive sphere_record(const Sphere& s, int material) {
    GpuPrimitive p;
    p.info = {GpuPrimitive::kSphere, std::uint32_t(material), 0, 0};
    p.p[0] = v4(s.center, s.radius);
    return p;
}

GpuPrimitive quad_record(const Quad& q, int material) {
    GpuPrimitive p;
    p.info = {GpuPrimitive::kQuad, std::uint32_t(material), 0, 0};
    p.p[0] = v4(q.origin);
    p.p[1] = v4(q.u);
    p.p[2] = v4(q.v);
    p.p[3] = v4(q.normal);
    p.p[4] = v4(q.a_axis);
    p.p[5] = v4(q.b_axis);
    return p;
}

GpuPrimitive triangle_record(const Triangle& t, int material) {
    GpuPrimitive p;
    p.info = {GpuPrimitive::kTriangle, std::uint32_t(material), 0, 0};
    p.p[0] = v4(t.p0);
    p.p[1] = v4(t.p1);
    p.p[2] = v4(t.p2);
    return p;
}

std::string named(const Material& m) {
    return m.type + " material '" + m.name + "'";
}

// What the exporter of one BSDF class is given: the material, the table's BSDF from outside and inside, and
// where its notes go (only for a material some shape uses).
struct MaterialExport {
    const Material& m;
    const Bsdf& outside;
    const Bsdf& inside;
    bool used;
    std::vector<std::string>& notes;
};
using ExportBsdf = void (*)(const MaterialExport& e, GpuMaterial& g);

void lambert_record(const MaterialExport& e, GpuMaterial& g) {
    g.info.x = GpuMaterial::kLambert;
    g.color = v4(static_cast<const LambertBrdf&>(e.outside).albedo);
}

void mirror_record(const MaterialExport& e, GpuMaterial& g) {
    g.info.x = GpuMaterial::kMirror;
    g.color = v4(static_cast<const MirrorBrdf&>(e.outside).reflectance);
}

void glossy_record(const MaterialExport& e, GpuMaterial& g) {
    const auto& glossy = static_cast<const GlossyBrdf&>(e.outside);
    g.info.x = GpuMaterial::kGlossy;
    g.color = v4(glossy.albedo, glossy.exponent);
}

void retroreflective_record(const MaterialExport& e, GpuMaterial& g) {
    const auto& retro = static_cast<const RetroreflectiveBrdf&>(e.outside);
    g.info.x = GpuMaterial::kRetroreflective;
    g.color = v4(retro.albedo, retro.exponent);
}

// Glass of class B from both sides, carrying radiance: the shaders' smooth interface, its two η.
template <class B>
void glass_record(const MaterialExport& e, GpuMaterial& g) {
    const auto& outside = static_cast<const B&>(e.outside);
    if (typeid(e.inside) != typeid(B) || outside.transport != Transport::kRadiance)
        throw std::logic_error(named(e.m) + ": the shaders trace radiance through glass only");
    g.info.x = GpuMaterial::kSmoothDielectric;
    g.eta = {float(outside.eta), float(static_cast<const B&>(e.inside).eta), 0.0f, 0.0f};
}

// Chapter 07's GGX glass is not in the shaders: the smooth interface of the same index stands in.
void rough_glass_record(const MaterialExport& e, GpuMaterial& g) {
    glass_record<RoughDielectric>(e, g);
    if (e.used) {
        char ior[32];
        std::snprintf(ior, sizeof ior, "%g", double(e.m.ior));
        e.notes.push_back(named(e.m) +
                          ": rough glass (GGX) is not in the shaders; shaded as smooth glass of ior " + ior +
                          " (chapter 07 renders it rough)");
    }
}

// Chapter 07's conductors are not in the shaders: a mirror of the metal's colour at normal incidence, F(0°),
// stands in.
void conductor_record(const MaterialExport& e, GpuMaterial& g) {
    const auto& metal = static_cast<const Conductor&>(e.outside);
    g.info.x = GpuMaterial::kMirror;
    g.color = v4(fresnel_conductor(1, metal.eta, metal.k));
    if (e.used) {
        e.notes.push_back(named(e.m) +
                          ": conductors (complex Fresnel, GGX) are not in the shaders; shaded as a " +
                          "mirror of its colour at normal incidence (chapter 07 renders it)");
    }
}

// The shaders' record of the table's BSDF for material i, by its class: the GPU cannot call a virtual
// function, so each BSDF is exported here, once. A class the shaders do not know is refused, as a light is.
GpuMaterial material_record(const Scene& scene, const MaterialTable& table, std::size_t i, bool used,
                            std::vector<std::string>& notes) {
    static const std::unordered_map<std::type_index, ExportBsdf> by_class{
        {typeid(LambertBrdf), lambert_record},
        {typeid(MirrorBrdf), mirror_record},
        {typeid(GlossyBrdf), glossy_record},
        {typeid(RetroreflectiveBrdf), retroreflective_record},
        {typeid(SmoothDielectric), glass_record<SmoothDielectric>},
        {typeid(RoughDielectric), rough_glass_record},
        {typeid(Conductor), conductor_record},
    };
    const Material& m = scene.materials[i];
    const int index = int(i);
    const Bsdf& outside = table.bsdf(index, true);
    const auto found = by_class.find(typeid(outside));
    if (found == by_class.end())
        throw InputError(named(m) + ": its BSDF is not in the shaders (the chapters before 11 render it)");
    if (m.two_sided)
        throw InputError(named(m) +
                         ": two-sided emission is not in the shaders (the chapters before 11 render it)");
    GpuMaterial g;
    g.emission = v4(table.emission(index, true));
    g.info.y = outside.flags().black ? 1u : 0u;
    found->second({m, outside, table.bsdf(index, false), used, notes}, g);
    if (!m.textures.empty() && used && !outside.flags().black) {
        notes.push_back(named(m) +
                        ": textures are not in the shaders; shaded as the texture's mean colour "
                        "(chapter 04 renders it textured)");
    }
    if (const Medium* interior = table.interior(index)) {
        if (typeid(*interior) != typeid(AbsorbingMedium))
            throw InputError(named(m) +
                             ": its medium is not in the shaders (the chapters before 11 render it)");
        g.info.z = 1u;
        g.absorption = v4(static_cast<const AbsorbingMedium&>(*interior).absorption);
    }
    return g;
}

GpuLight quad_light_record(const Light& light) {
    const QuadLight& q = static_cast<const QuadEmitter&>(light).quad();
    GpuLight l;
    l.info.x = GpuLight::kQuad;
    l.a = v4(q.origin);
    l.b = v4(q.u);
    l.c = v4(q.v, q.area);
    l.normal = v4(q.normal);
    l.radiance = v4(q.radiance);
    return l;
}

GpuLight triangle_light_record(const Light& light) {
    const TriangleLight& t = static_cast<const TriangleEmitter&>(light).triangle();
    GpuLight l;
    l.info.x = GpuLight::kTriangle;
    l.a = v4(t.p0);
    l.b = v4(t.p1);
    l.c = v4(t.p2, t.area);
    l.normal = v4(t.normal);
    l.radiance = v4(t.radiance);
    return l;
}

GpuLight sphere_light_record(const Light& light) {
    const SphereLight& s = static_cast<const SphereEmitter&>(light).sphere();
    GpuLight l;
    l.info.x = GpuLight::kSphere;
    l.a = v4(s.center, s.radius);
    l.radiance = v4(s.radiance);
    return l;
}

GpuLight point_light_record(const Light& light) {
    const PointLight& p = static_cast<const PointEmitter&>(light).point();
    GpuLight l;
    l.info.x = GpuLight::kPoint;
    l.a = v4(p.position);
    l.radiance = v4(p.intensity);
    return l;
}

GpuLight distant_light_record(const Light& light) {
    const auto& distant = static_cast<const DistantEmitter&>(light);
    GpuLight l;
    l.info.x = GpuLight::kDistant;
    l.a = v4(-distant.light().direction);
    l.b = v4(distant.scene().center, distant.scene().radius);
    l.radiance = v4(distant.light().irradiance);
    return l;
}

GpuLight spot_light_record(const Light& light) {
    const auto& spot = static_cast<const SpotEmitter&>(light);
    GpuLight l;
    l.info.x = GpuLight::kSpot;
    l.a = v4(spot.spot().position);
    l.b = v4(spot.axis(), spot.cos_end());
    l.c = v4(Vec3(spot.cos_start(), 0, 0));
    l.radiance = v4(spot.spot().intensity);
    return l;
}

// The record the shaders read for `light`, by its class (lights.glsl samples each kind).
GpuLight light_record(const Light& light) {
    using Record = GpuLight (*)(const Light&);
    static const std::unordered_map<std::type_index, Record> by_class{
        {typeid(QuadEmitter), quad_light_record},       {typeid(TriangleEmitter), triangle_light_record},
        {typeid(SphereEmitter), sphere_light_record},   {typeid(PointEmitter), point_light_record},
        {typeid(DistantEmitter), distant_light_record}, {typeid(SpotEmitter), spot_light_record},
    };
    const auto found = by_class.find(typeid(light));
    if (found == by_class.end())
        throw InputError(std::string(light.kind()) +
                         " lights are not in the shaders (chapter 06 renders them)");
    return found->second(light);
}

// The picker's lights in its order with P(light) and the cdf.
std::vector<GpuLight> light_records(const LightPicker& picker) {
    std::vector<GpuLight> out;
    if (picker.empty()) return out;
    for (std::size_t i = 0; i < picker.light_count(); ++i) out.push_back(light_record(picker.light(i)));
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i].normal.w = float(picker.probability(i));
        out[i].radiance.w = float(picker.cdf()[i]);
    }
    return out;
}

}  // namespace

GpuScene flatten_scene(const Scene& scene, const MaterialTable& materials, const LightSet& lights,
                       const LightPicker& picker) {
    GpuScene gpu;
    const std::vector<bool> used = scene.used_materials();
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        gpu.materials.push_back(material_record(scene, materials, i, used[i], gpu.notes));
    gpu.lights = light_records(picker);
    gpu.light_total = float(picker.total_weight());
    if (lights.environment && !is_black(lights.environment->radiance))
        gpu.environment = lights.environment->radiance;
    if (lights.environment && lights.environment->image) {
        gpu.notes.push_back("environment image " + lights.environment->image_file +
                            ": not in the shaders; shaded as a constant sky of its average radiance "
                            "(chapters 06 to 10 render the image, sampled by importance)");
    }

    // The shapes as chapter 02's World adds them, in scene order.
    PrimitiveList list(lights, picker);
    std::vector<Plane> planes;
    std::vector<int> plane_materials;
    for (const Shape& shape : scene.shapes) {
        const int material = shape.material;
        const bool emissive = scene.material_of(shape).emissive();
        std::visit(
            [&](const auto& g) {
                using T = std::decay_t<decltype(g)>;
                if constexpr (std::is_same_v<T, SphereShape>) {
                    const Sphere s{g.center, g.radius};
                    list.add(sphere_record(s, material), bounds_of(s), emissive);
                } else if constexpr (std::is_same_v<T, QuadShape>) {
                    const Quad q = make_quad(g.origin, g.u, g.v);
                    list.add(quad_record(q, material), bounds_of(q), emissive);
                } else if constexpr (std::is_same_v<T, TriangleShape>) {
                    const Triangle t{g.vertices[0], g.vertices[1], g.vertices[2]};
                    list.add(triangle_record(t, material), bounds_of(t), emissive);
                } else if constexpr (std::is_same_v<T, PlaneShape>) {
                    planes.push_back(make_plane(g.point, g.normal));
                    plane_materials.push_back(material);
                } else if constexpr (std::is_same_v<T, BoxShape>) {
                    for (const Quad& face : box_faces(g))
                        list.add(quad_record(face, material), bounds_of(face), emissive);
                } else if constexpr (std::is_same_v<T, MeshShape>) {
                    for (const auto& tri : g.triangles) {
                        const Triangle t{g.positions[tri[0]], g.positions[tri[1]], g.positions[tri[2]]};
                        list.add(triangle_record(t, material), bounds_of(t), emissive);
                    }
                }
            },
            shape.geometry);
    }
    // Chapter 02's BVH over them (one primitive a slot: the GPU's SIMD is across rays, not across the quads
    // of a packet), and the primitives laid out in its leaf order.
    if (!list.bounded.empty()) {
        std::vector<std::uint32_t> order;
        const Bvh bvh(list.bounds, order);
        gpu.nodes = bvh.nodes();
        for (std::uint32_t primitive : order) gpu.primitives.push_back(list.bounded[primitive]);
    }
    gpu.plane_first = std::uint32_t(gpu.primitives.size());
    gpu.plane_count = std::uint32_t(planes.size());
    for (std::size_t i = 0; i < planes.size(); ++i) {
        GpuPrimitive p;
        p.info = {GpuPrimitive::kPlane, std::uint32_t(plane_materials[i]), GpuPrimitive::kNoLight,
                  std::uint32_t(list.bounded.size() + i)};
        p.p[0] = v4(planes[i].point);
        p.p[1] = v4(planes[i].normal);
        p.p[2] = v4(planes[i].tangent);
        p.p[3] = v4(planes[i].bitangent);
        gpu.primitives.push_back(p);
    }
    return gpu;
}

std::size_t gpu_bytes(const GpuScene& scene) {
    return scene.nodes.size() * sizeof(BvhNode) + scene.primitives.size() * sizeof(GpuPrimitive) +
           scene.materials.size() * sizeof(GpuMaterial) + scene.lights.size() * sizeof(GpuLight);
}

}  // namespace rt
