#include "rt/io/scene_lights.hpp"

#include <algorithm>
#include <array>
#include <memory>

#include "rt/io/environment_image.hpp"

namespace rt::scene_reading {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kLightTypes[] = {"point", "distant", "spot", "environment"};

// A distant light: the way its light travels and the irradiance of a surface facing it.
DistantLight read_distant(const Node& node) {
    node.expect_object(std::array<std::string_view, 3>{"type", "direction", "irradiance"}, "a distant light");
    return DistantLight{glm::normalize(node["direction"].direction()),
                        node["irradiance"].color_in(kLargestNumber)};
}

// A spot light: its axis from `position` toward `at` (they must differ), its cone of cone_angle degrees in
// (0, 180] with a falloff band of cone_delta degrees in [0, cone_angle] at the edge.
SpotLight read_spot(const Node& node) {
    node.expect_object(
        std::array<std::string_view, 6>{"type", "position", "at", "intensity", "cone_angle", "cone_delta"},
        "a spot light");
    SpotLight spot;
    spot.position = node["position"].vec3();
    spot.at = node["at"].vec3();
    if (!normalisable(spot.at - spot.position)) {
        node["at"].fail(
            "must differ from position, so that at - position is a direction, got at - position = " +
            show(spot.at - spot.position));
    }
    spot.intensity = node["intensity"].color_in(kLargestNumber);
    if (node.has("cone_angle")) spot.cone_angle = node["cone_angle"].real_in(0, 180, true, false);
    if (node.has("cone_delta"))
        spot.cone_delta = node["cone_delta"].real_in(0, double(spot.cone_angle), false, false);
    if (spot.cone_delta > spot.cone_angle) {
        node["cone_angle"].fail("must be at least cone_delta (" + show(double(spot.cone_delta)) + "), got " +
                                show(double(spot.cone_angle)));
    }
    return spot;
}

// An environment light: a constant `radiance`, or an `image` (environment_image.hpp) with its `scale` and
// `rotate_y`. The image's radiance, once scaled, is at most kLargestNumber, as every radiance in a scene.
EnvironmentLight read_environment(const Node& node, const fs::path& scene_folder) {
    node.expect_object(std::array<std::string_view, 5>{"type", "radiance", "image", "scale", "rotate_y"},
                       "an environment light");
    if (!node.has("image")) {
        if (node.has("scale") || node.has("rotate_y"))
            node[node.has("scale") ? "scale" : "rotate_y"].fail("applies only to an environment image");
        return EnvironmentLight{node["radiance"].color_in(kLargestNumber)};
    }
    if (node.has("radiance")) node["radiance"].fail("an environment light has a radiance or an image, not both");
    EnvironmentLight light;
    const Node file = node["image"];
    light.image_file = file.string();
    if (node.has("scale")) light.scale = node["scale"].real_in(0, kLargestNumber, true, false);
    if (node.has("rotate_y")) light.rotate_y = node["rotate_y"].real_in(-360, 360, false, false);
    const fs::path path = scene_folder / light.image_file;
    auto image = std::make_shared<Image>();
    try {
        *image = read_environment_image(path);
    } catch (const InputError& e) {
        file.fail(e.what());
    }
    // The radiance the chapters before 06 shade it as: the average over the sphere, each row weighted by the
    // solid angle of its band (sin θ at its centre).
    Vec3d sum(0);
    double weights = 0;
    for (int y = 0; y < image->height(); ++y) {
        const double sin_theta = std::sin(kPi * (y + 0.5) / image->height());
        for (int x = 0; x < image->width(); ++x) {
            const Vec3d scaled = Vec3d(image->at(x, y)) * double(light.scale);
            const double brightest = std::max({scaled.x, scaled.y, scaled.z});
            if (brightest > kLargestNumber) {
                const std::string pixel = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
                const std::string why = ", above " + show(kLargestNumber) +
                                        ", the limit of every radiance in a scene (as of emission, intensity " +
                                        "and radiance), which keeps chapter 11's float sums of samples finite";
                if (node.has("scale")) {
                    node["scale"].fail(show(double(light.scale)) + " makes " + pixel + " of the image " +
                                       show(brightest) + why);
                }
                file.fail(shown_name(light.image_file) + ": " + pixel + " is " + show(brightest) + why);
            }
            sum += scaled * sin_theta;
        }
        weights += sin_theta * image->width();
    }
    light.radiance = Color(sum / weights);
    light.image = std::move(image);
    return light;
}

}  // namespace

void read_light(const Node& node, Scene& scene, const fs::path& scene_folder) {
    if (!node.json().is_object()) node.fail("must be an object, got " + std::string(node.json().type_name()));
    const std::string type = node["type"].string();
    if (type == "point") {
        node.expect_object(std::array<std::string_view, 3>{"type", "position", "intensity"}, "a point light");
        scene.point_lights.push_back({node["position"].vec3(), node["intensity"].color_in(kLargestNumber)});
    } else if (type == "distant") {
        scene.distant_lights.push_back(read_distant(node));
    } else if (type == "spot") {
        scene.spot_lights.push_back(read_spot(node));
    } else if (type == "environment") {
        if (scene.environment) node.fail("a scene has at most one environment light");
        scene.environment = read_environment(node, scene_folder);
    } else {
        node["type"].fail("unknown light type " + quote(type) + suggestion(type, kLightTypes) +
                          "; expected point, distant, spot or environment");
    }
}

}  // namespace rt::scene_reading
