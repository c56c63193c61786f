// The pinhole camera: every ray starts at the eye and passes through a point of the film (the image plane
// at distance 1 along the view direction).
#pragma once

#include "rt/core/math.hpp"
#include "rt/core/ray.hpp"
#include "rt/core/scene.hpp"

namespace rt {

struct PinholeCamera {
    Vec3 eye;
    Vec3 forward;  // w = (at − from) / |at − from|
    Vec3 right;    // u = (w × up) / |w × up|
    Vec3 up;       // v = u × w
    Real half_width;   // tan(vfov / 2) · width / height
    Real half_height;  // tan(vfov / 2)
    int width;
    int height;
};

// Builds the camera basis in double precision, so an `up` nearly parallel to the view still gives an
// orthonormal basis. Throws InputError when `up` is exactly parallel to the view direction, or the image
// size is not positive.
PinholeCamera make_pinhole_camera(const CameraDesc& desc, int width, int height);

// The film point (px, py), in pixels from the top-left corner, seen from the eye (not normalised):
// d(px, py) = w + (2 px / W − 1) · half_width · u + (1 − 2 py / H) · half_height · v
Vec3 film_direction(const PinholeCamera& camera, Real px, Real py);

// The ray from the eye through film point (px, py), with a unit direction.
Ray camera_ray(const PinholeCamera& camera, Real px, Real py);

}  // namespace rt
