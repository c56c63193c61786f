#include "guide_picture.hpp"

#include <algorithm>

#include "01_ray_generation/camera_render.hpp"
#include "equal_area_map.hpp"
#include "rt/io/false_colour.hpp"
#include "rt/render/render_loop.hpp"

namespace rt {

namespace {

// Chapter 06's path state, but the light met at the first vertex (an emitter seen straight, or the sky) is
// left out: what remains arrived by scattering.
struct ScatteredLight : PathState {
    void add_met(const Color& term) {
        if (depth > 0) L += term;
    }
};

// Paints `values` (a side × side panel) into `image` at column x0, in false colour scaled to their maximum.
void paint(Image& image, int x0, int side, const std::vector<double>& values) {
    const double top = std::max(1e-30, *std::max_element(values.begin(), values.end()));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            image.at(x0 + x, y) = linear_of_display(false_colour(values[std::size_t(y * side + x)] / top));
}

}  // namespace

Image guide_picture(const GuidingField& field, const PathTracer& tracer, const GuidePictureRequest& request,
                    int threads) {
    const int side = request.size, gap = side / 16;
    const DirectionalQuadtree empty;
    const DirectionalQuadtree* learned = field.guide_at(request.at);
    const DirectionalQuadtree& guide = learned ? *learned : empty;
    std::vector<double> density(std::size_t(side * side));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            density[std::size_t(y * side + x)] =
                double(guide.pdf_square(Vec2((Real(x) + 0.5f) / Real(side), (Real(y) + 0.5f) / Real(side))));
    // The right panel: each pixel's direction jittered within it, `paths` unguided paths each.
    const RenderSettings settings{side, side, request.paths, 1, threads, ProgressStyle::kNone};
    const RenderResult incident = render(settings, [&](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        const Vec2 p((Real(s.x) + rng.next_real()) / Real(side), (Real(s.y) + rng.next_real()) / Real(side));
        ScatteredLight path;
        tracer.trace(Ray{request.at, equal_area_direction(p)}, path, SampleStream(rng), rays, nullptr,
                     SurfacePaths(tracer));
        return finite_or_black(path.L);
    });
    std::vector<double> radiance(std::size_t(side * side));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            radiance[std::size_t(y * side + x)] = double(luminance(incident.image.at(x, y)));
    Image picture(2 * side + gap, side);
    paint(picture, 0, side, density);
    paint(picture, side + gap, side, radiance);
    return picture;
}

}  // namespace rt
