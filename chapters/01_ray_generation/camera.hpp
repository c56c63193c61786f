// The pinhole camera: every ray starts at the eye and passes through a point of the film (the image plane
// at distance 1 along the view direction). With an aperture it is a thin lens: a ray starts at a point of
// the lens disk (radius `aperture`, centred on the eye, in the plane of u and v) and passes through the
// point where the pinhole ray of the same film point meets the plane in focus, at `focus_distance` along w.
// Every ray of one film point meets there, so that plane is sharp; a point at another depth spreads over a
// disk of confusion on the film of radius (in film units, the film at distance 1)
//   c = aperture · |1 / focus_distance − 1 / depth|.
#pragma once

#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct PinholeCamera {
    Vec3 eye;
    Vec3 forward;  // w = (at − from) / |at − from|
    Vec3 right;    // u = (w × up) / |w × up|, negated for a mirrored (left-handed) camera
    Vec3 up;       // v = u × w
    Real half_width;   // tan(vfov / 2) · width / height
    Real half_height;  // tan(vfov / 2)
    int width;
    int height;
    Real lens_radius = 0;     // the scene's camera.aperture; 0 is the pinhole
    Real focus_distance = 1;  // along w; the scene's, or |at − from|
};

// Builds the camera basis in double precision, so an `up` nearly parallel to the view still gives an
// orthonormal basis. Throws InputError when `up` is exactly parallel to the view direction, the image size
// is not positive, the aperture is negative or the focus distance is not positive.
PinholeCamera make_pinhole_camera(const CameraDesc& desc, int width, int height);

// The film point (px, py), in pixels from the top-left corner, seen from the eye (not normalised):
// d(px, py) = w + (2 px / W − 1) · half_width · u + (1 − 2 py / H) · half_height · v
Vec3 film_direction(const PinholeCamera& camera, Real px, Real py);

// The ray from the eye through film point (px, py), with a unit direction.
Ray camera_ray(const PinholeCamera& camera, Real px, Real py);

// Through the thin lens: the ray from the lens point that u_lens in [0, 1)² places (concentric map, uniform
// on the disk) through film point (px, py)'s point in focus, eye + focus_distance · d(px, py).
Ray thin_lens_ray(const PinholeCamera& camera, Real px, Real py, Vec2 u_lens);

}  // namespace rt
