// The pinhole camera seen from the scene: which pixel a point projects to, and the camera's importance We.
// A pixel's value is the radiance averaged over its patch of the film (chapter 01: the film is the plane at
// distance 1 along w, a pixel covers A_pix = (2 half_width)(2 half_height) / (W H) of it):
//   I_j = (1 / A_pix) ∫_pixel L dA_film.
// A film point at angle θ_c from w is 1 / cos θ_c from the eye and the film is tilted by θ_c to the ray, so
// dA_film = dω / cos³θ_c, and I_j = ∫ We L cos θ_c dω with We over the pixel's directions (0 elsewhere)
// the function of θ_c that makes the two agree: the importance a light path is weighted by at the camera.
#pragma once

#include <optional>
#include <string>

#include "01_ray_generation/camera.hpp"
#include "rt/core/math.hpp"
#include "rt/core/scene.hpp"

namespace rt {

// Where a direction from the eye meets the film.
struct FilmPoint {
    Real px = 0;         // in pixels from the left
    Real py = 0;         // in pixels from the top
    Real cos_theta = 1;  // cos θ_c = w · d / |d|
    int x = 0;           // the pixel: (⌊px⌋, ⌊py⌋)
    int y = 0;
};

// The film point of the direction d from the eye (any length): chapter 01's film_direction inverted (scale d to
// the film plane at distance 1 along w, then its coordinates along u and v to pixels). Nothing when d points
// behind the eye or the point falls outside the film.
std::optional<FilmPoint> project_direction(const PinholeCamera& camera, const Vec3& d);
// The film point of the scene point x: project_direction(x − eye).
std::optional<FilmPoint> project_point(const PinholeCamera& camera, const Vec3& x);

// A_pix = 4 half_width half_height / (W H): one pixel's area on the film at distance 1.
Real pixel_area(const PinholeCamera& camera);

// We: the importance of a direction at angle θ_c from the view, within its pixel.
Real pinhole_importance(const PinholeCamera& camera, Real cos_theta);

// The camera light paths connect to: the scene's, as a pinhole. This chapter's importance is a pinhole's;
// a scene's thin lens (chapter 01's aperture) is not simulated by light paths, and the pinhole at the lens
// centre stands in for it (`--tracer reverse` renders its depth of field).
PinholeCamera light_tracing_camera(const Scene& scene, int width, int height);
// The run's note saying so, when the scene's camera has an aperture; empty otherwise.
std::string lens_stand_in_note(const Scene& scene);

}  // namespace rt
