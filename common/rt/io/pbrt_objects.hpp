// The things a pbrt-v4 scene names (materials, shapes, lights) translated into the course's scene JSON, one
// function each; pbrt_reader.cpp calls them with the parameters and the graphics state of each directive.
#pragma once

#include <glm/mat4x4.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rt/io/pbrt_parameters.hpp"

namespace rt::pbrt {

using Json = nlohmann::json;

// A named texture (Texture "name" "spectrum" "imagemap" ...): its pbrt type, spectrum or float, and the
// course's texture object (assets/scenes/README.md, "A texture").
struct Texture {
    std::string type;
    Json course;
};
using Textures = std::map<std::string, Texture, std::less<>>;

// A texture of class imagemap (an 8-bit PNG or JPEG) or checkerboard (of two values); `type_place` refuses
// another class.
Json texture(const std::string& kind, const std::string& type, PbrtParameters& params,
             const std::string& type_place, std::vector<std::string>& notes);

// A material: diffuse, conductor, dielectric or coateddiffuse, its colours rgb values or `textures`;
// `type_place` refuses another type. What it reads but the course's image does not show is added to `notes`.
Json material(const std::string& type, PbrtParameters& params, const std::string& type_place,
              const Textures& textures, std::vector<std::string>& notes);

// An area light as the keys its shapes' material gains: "emission" L × scale, and "two_sided" true where
// the light is "twosided".
Json area_emission(PbrtParameters& params);

// A shape under the transform `ctm` (object to world), its orientation reversed or not, as a course shape
// without its "material". `emissive`: it is an area light, whose emitting side must be expressible.
Json shape(const std::string& type, PbrtParameters& params, const glm::dmat4& ctm, bool reverse_orientation,
           bool emissive, const std::string& type_place);

// A light source (point, spot, distant, or infinite with a constant L): {"type": ...} of the course's lights.
Json light(const std::string& type, PbrtParameters& params, const glm::dmat4& ctm, const std::string& type_place);

}  // namespace rt::pbrt
