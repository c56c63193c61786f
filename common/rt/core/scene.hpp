// The scene description: plain data, as read from a scene file (see assets/scenes/README.md). Each chapter
// turns it into what it can simulate.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/mat4x4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rt/core/effect_set.hpp"
#include "rt/core/enum_names.hpp"
#include "rt/core/image.hpp"
#include "rt/core/math.hpp"

namespace rt {

struct CameraDesc {
    Vec3 from{0, 0, 0};
    Vec3 at{0, 0, -1};
    Vec3 up{0, 1, 0};
    Real vfov = 40;  // vertical field of view, degrees
    // A thin lens (chapter 01): the lens disk's radius (0: a pinhole) and the distance along the view
    // direction of the plane in focus (unset: |at − from|).
    Real aperture = 0;
    std::optional<Real> focus_distance{};
    // A left-handed camera (pbrt's): the picture's right is up × view instead of view × up, so the image
    // comes out mirrored left to right against the course's own camera.
    bool mirrored = false;
};

// The deepest path a scene or --max-depth may ask for.
inline constexpr int kMaxPathDepth = 1024;

struct ImageDesc {
    int width = 320;
    int height = 240;
    int spp = 16;  // samples per pixel
};

// A homogeneous participating medium (chapter 09): per unit of length, light is absorbed at the rate sigma_a
// and scattered at the rate sigma_s, per colour channel; g is the Henyey–Greenstein asymmetry of the
// scattering (0 isotropic, > 0 forward, < 0 backward), in (−1, 1).
struct MediumDesc {
    Color sigma_a{0};
    Color sigma_s{0};
    Real g = 0;

    Color sigma_t() const { return sigma_a + sigma_s; }  // extinction
    bool scatters() const { return sigma_s.r > 0 || sigma_s.g > 0 || sigma_s.b > 0; }
};

// A texture in place of a colour parameter (chapter 04 evaluates it at a hit's uv; see texture.hpp there).
// An image, read once when the scene is loaded: texels in linear RGB, row 0 at the top of the picture.
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<Color> texels;  // width · height, row by row
};
enum class TextureWrap { kRepeat, kClamp };        // what a coordinate outside [0, 1) reads
enum class TextureFilter { kBilinear, kNearest };  // how texels between texel centres are blended
enum class TextureEncoding { kSrgb, kLinear };     // how the file's 8-bit values map to linear RGB
constexpr auto names_of(TextureWrap) {
    return enum_names<TextureWrap>("wrap",
                                   {{TextureWrap::kRepeat, "repeat"}, {TextureWrap::kClamp, "clamp"}});
}
constexpr auto names_of(TextureFilter) {
    return enum_names<TextureFilter>(
        "filter", {{TextureFilter::kBilinear, "bilinear"}, {TextureFilter::kNearest, "nearest"}});
}
constexpr auto names_of(TextureEncoding) {
    return enum_names<TextureEncoding>(
        "encoding", {{TextureEncoding::kSrgb, "srgb"}, {TextureEncoding::kLinear, "linear"}});
}
struct ImageTextureDesc {
    std::string file;                           // as the scene file names it
    std::shared_ptr<const TextureImage> image;  // shared: copies of a Scene do not copy the texels
    Vec2 scale{1};                              // (su, sv): the image repeats su times along u, sv along v
    TextureWrap wrap = TextureWrap::kRepeat;
    TextureFilter filter = TextureFilter::kBilinear;
};
// Squares of side 1 / scale in uv: even where ⌊scale·u⌋ + ⌊scale·v⌋ is even, odd elsewhere.
struct CheckerDesc {
    Color even{1};
    Color odd{0};
    Real scale = 1;
};
struct TextureDesc {
    std::variant<ImageTextureDesc, CheckerDesc> pattern;
    Color mean{0};   // its average colour over a period: what a chapter without textures shades it as
    Color least{0};  // its least value per channel (a conductor's index must not be 0 anywhere)
};

// A material as the scene file gives it: its type's name and the parameters of the course's types. What
// each type reads, the effect it needs and its stand-in are its MaterialKind's (rt/io/material_kind.hpp).
struct Material {
    // A colour parameter given as a texture instead of [r, g, b]: which one (&Material::albedo, ...) and the
    // texture; the parameter itself then holds the texture's mean.
    struct Textured {
        Color Material::*parameter;
        TextureDesc texture;
    };

    std::string name;
    std::string type = "diffuse";  // as the scene file spells it: a MaterialKind's name
    Color albedo{0.8f};            // diffuse, glossy, retroreflective: reflectance in [0, 1]
    Color reflectance{1.0f};       // mirror: the fraction reflected
    Color emission{0.0f};          // radiance emitted (any type): makes its shapes area lights
    bool two_sided = false;        // the emission leaves both sides, not only the front
    Real roughness = 0.2f;         // glossy, retroreflective: width of the lobe in (0, 1]; dielectric and
                            // conductor: 0 is smooth, r > 0 rough (GGX microfacets of α = r², chapter 07)
    Real ior = 1.5f;                   // dielectric: index of refraction
    Color absorption{0.0f};            // dielectric: Beer–Lambert absorption coefficient per unit length
    std::optional<MediumDesc> medium;  // dielectric: a participating medium inside (instead of absorption)
    Color eta{1};  // conductor: the real part η of the complex index of refraction η + i k
    Color k{0};    // conductor: its imaginary part, the extinction coefficient
    std::vector<Textured> textures;  // the colour parameters given as textures, in the file's order

    bool emissive() const { return emission.r > 0 || emission.g > 0 || emission.b > 0; }
};

// Scale, then rotations about x, y and z (degrees), then translation; or, for a mesh, any affine matrix
// instead (a pbrt scene's transform).
struct Transform {
    Vec3 scale{1};
    Vec3 rotate_degrees{0};
    Vec3 translate{0};
    std::optional<glm::dmat4> matrix;  // when set, the three above are unused

    Vec3 apply_to_point(const Vec3& p) const;
    // A surface normal follows the inverse transpose: n / scale, then the rotations (not normalised).
    Vec3 apply_to_normal(const Vec3& n) const;
    // Whether it turns the space inside out, as a mirror does: an odd number of negative scale factors (a
    // matrix of negative determinant).
    bool mirrors() const;

  private:
    Vec3 rotate(Vec3 v) const;  // about x, then y, then z
};

struct SphereShape {
    Vec3 center{0};
    Real radius = 1;
};
// The parallelogram origin + a·u + b·v, a and b in [0, 1]; its front side is the side of u × v.
struct QuadShape {
    Vec3 origin{0};
    Vec3 u{1, 0, 0};
    Vec3 v{0, 1, 0};
};
struct TriangleShape {
    std::array<Vec3, 3> vertices{};
};
struct PlaneShape {
    Vec3 point{0};
    Vec3 normal{0, 1, 0};
};
struct BoxShape {
    Vec3 min{0};
    Vec3 max{1};
    Transform transform;
};
// A triangle mesh with shared vertices; positions and normals are already transformed into the scene. A file
// that gives vertex normals (OBJ vn, PLY nx ny nz) or texture coordinates (OBJ vt, PLY u v) has them here,
// with each triangle's corners into them (OBJ indexes them apart from the positions); a mesh without normals
// is shaded faceted, by its triangles' own normals.
struct MeshShape {
    std::string file;
    Transform transform;
    std::vector<Vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<Vec3> normals;                                  // unit; empty when the file has none
    std::vector<std::array<std::uint32_t, 3>> normal_corners;   // per triangle, or empty
    std::vector<Vec2> texture_coordinates;                      // empty when the file has none
    std::vector<std::array<std::uint32_t, 3>> texture_corners;  // per triangle, or empty

    bool smooth() const { return !normals.empty(); }
};

struct Shape {
    std::variant<SphereShape, QuadShape, TriangleShape, PlaneShape, BoxShape, MeshShape> geometry;
    int material = 0;   // index into Scene::materials
    std::string place;  // where it stands in the file, e.g. "shapes[3]"
};

struct PointLight {
    Vec3 position{0};
    Color intensity{1};  // radiant intensity, W/sr
};
// Parallel light from far away (the sun): `direction` (unit) is the way it travels; a surface facing it
// receives `irradiance`, W/m².
struct DistantLight {
    Vec3 direction{0, -1, 0};
    Color irradiance{1};
};
// A point light shining from `position` toward `at` (pbrt's spot): its full intensity within
// cone_angle − cone_delta degrees of that axis, falling off smoothly to zero at cone_angle.
struct SpotLight {
    Vec3 position{0};
    Vec3 at{0, -1, 0};
    Color intensity{1};  // W/sr, on the axis
    Real cone_angle = 30;
    Real cone_delta = 5;
};
// The light of every ray that leaves the scene: one constant radiance, or an image in latitude–longitude
// (row 0 looks up, +y; the map turned by rotate_y degrees about +y), which chapter 06 samples by importance.
struct EnvironmentLight {
    EnvironmentLight() = default;
    explicit EnvironmentLight(Color constant) : radiance(constant) {}

    Color radiance{1};  // with an image: its average over the sphere times scale (what chapters 03–05 shade)
    std::shared_ptr<const Image> image;  // none for a constant
    std::string image_file;              // the file as the scene names it, for notes
    Real scale = 1;                      // the image's radiance is scale × its pixels
    Real rotate_y = 0;                   // degrees, counter-clockwise looking down +y
};

// A file the scene read: the scene file itself, a mesh, a texture or an environment image. A run may write no
// output over it (run_files.hpp).
struct SceneInput {
    std::string what;            // "the texture of materials.wood"
    std::filesystem::path path;  // as it was opened: the scene's folder joined with the name the scene gives
};

struct Scene {
    std::string file;                // where it was loaded from, for messages
    std::vector<SceneInput> inputs;  // every file it read, in the order read: the scene file first
    CameraDesc camera;
    ImageDesc image;
    std::vector<Material> materials;
    std::vector<Shape> shapes;
    std::vector<PointLight> point_lights;
    std::vector<DistantLight> distant_lights;
    std::vector<SpotLight> spot_lights;
    std::optional<EnvironmentLight> environment;
    std::optional<MediumDesc> medium;  // what fills the space outside every shape, where the camera is (fog)
    std::optional<EffectSet> effects;  // the scene's explicit list, when it has one
    // The path depth the scene asks for (pbrt's maxdepth): bounces after the camera ray, at most; --max-depth
    // overrides it. None: each chapter's own rule.
    std::optional<int> max_depth;
    // What the scene file said that changes nothing in the course's image (a pbrt scene's sampler type, its
    // pixel filter), for the run's summary.
    std::vector<std::string> notes;

    const Material& material_of(const Shape& shape) const { return materials[std::size_t(shape.material)]; }
    bool has_area_lights() const;
    // Point, distant or spot lights: the lights no ray meets.
    bool has_delta_lights() const;
    // Any light at all: area lights, delta lights, an environment.
    bool has_lights() const;
    // used[i]: whether some shape is made of material i.
    std::vector<bool> used_materials() const;
};

}  // namespace rt
