// The scene flattened into GPU buffers: what the shaders read (shaders/scene.glsl, materials.glsl,
// lights.glsl), as arrays of plain records in std430 layout. A GPU has no pointers into the CPU's memory and
// no virtual functions, so everything a render needs is copied into a few arrays and every "which kind is
// it" becomes a number in the record:
//   - chapter 02's BVH, its nodes as they are: 32 bytes, depth first (an interior node's first child follows
//     it, `offset` names the second), uploaded byte for byte;
//   - the primitives in the BVH's leaf order (a leaf's primitives are neighbours in memory), then the planes;
//   - chapter 04's material table, each BSDF asked what it is (the one place the GPU's switch is decided);
//   - chapter 04's light picker: its lights in its order with its cdf.
// Every record is a few vec4 (16 bytes: std430 aligns a vec3 like a vec4), an array of structs (AoS): one
// record is one contiguous read.
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>
#include <optional>
#include <string>
#include <vector>

#include "02_intersection/bvh.hpp"
#include "04_direct_lighting/light_picker.hpp"
#include "04_direct_lighting/material_table.hpp"
#include "rt/core/scene.hpp"

namespace rt {

using GpuVec4 = glm::vec4;  // float whatever Real is: the GPU computes in float
using GpuUvec4 = glm::uvec4;

// shaders/scene.glsl's Primitive: info = (kind, material, light, id), p[6] by kind.
struct GpuPrimitive {
    enum Kind : std::uint32_t { kSphere = 0, kQuad = 1, kTriangle = 2, kPlane = 3 };
    static constexpr std::uint32_t kNoLight = 0xFFFFFFFFu;
    GpuUvec4 info{0};
    GpuVec4 p[6]{};
};
static_assert(sizeof(GpuPrimitive) == 112);

// shaders/materials.glsl's Material.
struct GpuMaterial {
    enum Kind : std::uint32_t {
        kLambert = 0,
        kMirror = 1,
        kGlossy = 2,
        kRetroreflective = 3,
        kSmoothDielectric = 4
    };
    GpuUvec4 info{0};  // (kind, black, has interior, 0)
    GpuVec4 color{0};  // albedo or reflectance; w: Phong exponent
    GpuVec4 eta{1};    // (η from outside, η from inside)
    GpuVec4 emission{0};
    GpuVec4 absorption{0};
};
static_assert(sizeof(GpuMaterial) == 80);

// shaders/lights.glsl's Light.
struct GpuLight {
    enum Kind : std::uint32_t { kQuad = 0, kTriangle = 1, kSphere = 2, kPoint = 3, kDistant = 4, kSpot = 5 };
    GpuUvec4 info{0};
    GpuVec4 a{0}, b{0}, c{0};
    GpuVec4 normal{0};    // w: P(light)
    GpuVec4 radiance{0};  // w: the cdf
};
static_assert(sizeof(GpuLight) == 96);

static_assert(sizeof(BvhNode) == 32, "the shaders read a node as two vec4");

struct GpuScene {
    std::vector<BvhNode> nodes;
    std::vector<GpuPrimitive> primitives;  // the BVH's leaf order, then the planes
    std::uint32_t plane_first = 0;
    std::uint32_t plane_count = 0;
    std::vector<GpuMaterial> materials;
    std::vector<GpuLight> lights;      // the picker's order; empty when no light emits any power
    float light_total = 0;             // LightPicker::total_weight
    std::optional<Color> environment;  // a uniform environment that is not black
    std::vector<std::string> notes;    // what is shaded by a stand-in, for the run's summary
};

// Flattens `scene` with the render's material table and lights. Chapter 07's rough glass becomes smooth glass
// of its index, and its conductors mirrors of their colour at normal incidence, each with a note. Throws
// std::logic_error for a BSDF or medium the shaders do not know (a later chapter's), or one made for
// importance rather than radiance.
GpuScene flatten_scene(const Scene& scene, const MaterialTable& materials, const LightSet& lights,
                       const LightPicker& picker);

// The bytes the flattened scene takes on the GPU.
std::size_t gpu_bytes(const GpuScene& scene);

}  // namespace rt
