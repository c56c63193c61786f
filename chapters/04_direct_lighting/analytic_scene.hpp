// The analytic scene: one diffuse plane lit by one emissive quad above it, and nothing else. No shadow can
// fall, so the direct term is known exactly at every point: L = ρ / π · E(p), with E from Lambert's polygon
// formula (irradiance.hpp). Rendered with pixel-centre camera rays, each pixel has an exact value, and the
// renderer's error is the light sampling's alone.
#pragma once

#include <optional>

#include "01_ray_generation/camera.hpp"
#include "02_intersection/world.hpp"
#include "area_lights.hpp"
#include "material_table.hpp"
#include "rt/core/image.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct PlaneUnderQuad {
    Color albedo{0.8f};  // the plane's (Lambert)
    QuadLight light;
    int light_material = -1;  // the lamp's material: a hit with it is on the light
};

// The scene's plane and light when it is exactly one plane shaded as Lambert (in `materials`) and one
// emissive quad whose four corners lie strictly on the plane's front side, with no point or environment
// light; nothing otherwise.
std::optional<PlaneUnderQuad> find_plane_under_quad(const Scene& scene, const MaterialTable& materials);

// The exact radiance along a ray: ρ / π · E(p) on the plane (E = 0 behind the one-sided light), L on the
// light's front, 0 elsewhere. E is computed in double.
Color exact_radiance(const PlaneUnderQuad& analytic, const World& world, const Ray& ray);

// The exact image of pixel-centre rays (film point (x + ½, y + ½)).
Image exact_image(const PlaneUnderQuad& analytic, const World& world, const PinholeCamera& camera);

}  // namespace rt
