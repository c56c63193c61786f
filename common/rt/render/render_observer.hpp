// What watches a render as it goes without changing it: what each pixel's samples cost (the app's --heat,
// heat_maps.hpp) and the image after each whole pass (the live view). The render loop tells the observer
// of its settings (RenderSettings::observer); chapter 08's light tracer and chapter 11's shader tell it
// after each wave or pass of their own. None by default, and then nothing is measured.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>

#include "rt/core/image.hpp"
#include "rt/core/ray_counts.hpp"

namespace rt {

// What a pixel's samples cost: the rays they traced (every kind), the bounces among them (reflection,
// refraction and indirect rays: the path length beyond the first hit) and the samples taken.
struct PixelCost {
    std::uint64_t rays = 0;
    std::uint64_t bounces = 0;
    std::uint64_t samples = 0;
};

// What the render has after a pass: its image so far (every pixel's mean), the fewest samples a pixel has
// and the samples the image holds (a resumed render's included), the rays traced and the samples taken by
// this run so far, and the time since it started. Chapter 08's light tracer, whose paths splat into any
// pixel, reports after each wave of paths: its image is the splats' sum over the paths traced, and each
// pixel "has" the paths per pixel.
struct PassReport {
    const Image& image;
    std::uint32_t fewest_samples = 0;
    std::uint64_t samples_held = 0;
    RayCounts rays;
    std::uint64_t samples = 0;
    double seconds = 0;
};

class RenderObserver {
public:
    virtual ~RenderObserver() = default;
    // Whether add_cost is wanted (the loop then counts each pixel's rays apart).
    virtual bool measures_cost() const { return false; }
    // What one whole pass of a tile cost pixel (x, y), once the pass is kept. Called on the rendering
    // threads, never on two at once for one pixel.
    virtual void add_cost(int /*x*/, int /*y*/, const PixelCost& /*cost*/) {}
    // After each whole pass, on the rendering thread; the render goes on when it returns.
    virtual void after_pass(const PassReport& /*report*/) {}
};

// An observer that calls `f` after each pass (the live view, tests).
class AfterEachPass final : public RenderObserver {
public:
    explicit AfterEachPass(std::function<void(const PassReport&)> f) : f_(std::move(f)) {}
    void after_pass(const PassReport& report) override { f_(report); }

private:
    std::function<void(const PassReport&)> f_;
};

}  // namespace rt
