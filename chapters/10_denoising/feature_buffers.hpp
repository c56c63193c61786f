// The feature buffers (AOVs) of a render: beside the noisy image, what each pixel's paths met at their first
// vertex that is not a delta bounce (path_features.hpp, watching chapter 09's path loop): the albedo,
// the shading normal and the depth, having followed mirrors and glass as production renderers do. Each is the
// mean over the pixel's samples, with the variance of that mean, from exact sums of the samples and of their
// squares (rt/core/pixel_sums.hpp's variance_of_mean):
//   Var[mean] = (Σx² − (Σx)²/n) / (n (n − 1)).
// A denoiser is guided by them; an external one (Open Image Denoise, OptiX) can take them as they are.
#pragma once

#include "06_monte_carlo/path_tracer.hpp"
#include "rt/core/image.hpp"
#include "rt/core/scene.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

struct FeatureBuffers {
    Image colour, colour_variance;  // the noisy image and the variance of each pixel's mean, per channel
    Image albedo, albedo_variance;
    Image normal, normal_variance;  // the mean of unit normals (shorter where a pixel sees several)
    Image depth, depth_variance;    // the same value in all three channels; 0 where every path left the scene
};

struct FeatureRender {
    RenderResult result;  // its image is buffers.colour
    FeatureBuffers buffers;
};

// Renders `scene` through chapter 09's path loop on its material table (as ch09_participating_media does
// when it traces paths), recording the features of every sample. Refuses (std::logic_error) a resumed render.
FeatureRender render_features(const Scene& scene, const RenderSettings& settings, PathOptions options);

}  // namespace rt
