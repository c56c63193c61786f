// libFuzzer target for OBJ meshes as the scene loader reads them: the bytes become an OBJ file that a fixed
// scene uses as a mesh. Loading either gives triangles whose indices are in range and whose vertices are
// finite, or an InputError with a one-line message; anything else is a bug the fuzzer reports. The OBJ reader
// is the course's own (common/rt/io/obj_parser.cpp), built with the sanitizers; obj_parser_fuzz feeds it alone.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include "fuzz_promise.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/scene_loader.hpp"

namespace {

namespace fs = std::filesystem;

// A folder of this process's own, made and removed for every input (libFuzzer ends without destructors). In
// memory (/dev/shm) where there is one: on ext4, truncating and rewriting a file flushes it to disk on close,
// which costs milliseconds.
fs::path fuzz_folder() {
    std::error_code ec;
    const fs::path base = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
    return base / ("rt_mesh_loader_fuzz_" + std::to_string(::getpid()));
}
const fs::path kFolder = fuzz_folder();
const std::string kScene = R"({"camera": {"from": [0, 0, 5], "at": [0, 0, 0]},
  "materials": {"white": {"type": "diffuse"}},
  "shapes": [{"type": "mesh", "file": "fuzz.obj", "material": "white", "transform": {"scale": 2}}]})";

void expect(bool holds, const char* promise) {
    expect_promise(holds, "mesh_loader_fuzz", promise);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fs::create_directories(kFolder);
    std::ofstream(kFolder / "fuzz.obj", std::ios::binary)
        .write(reinterpret_cast<const char*>(data), long(size));
    const fs::path scene_file = kFolder / "scene.json";
    try {
        const rt::Scene scene = rt::parse_scene(kScene, scene_file);
        const auto& mesh = std::get<rt::MeshShape>(scene.shapes.at(0).geometry);
        expect(!mesh.triangles.empty(), "a mesh has triangles");
        for (const auto& triangle : mesh.triangles) {
            for (const std::uint32_t i : triangle) expect(i < mesh.positions.size(), "indices are in range");
        }
        for (const rt::Vec3& p : mesh.positions) expect(rt::is_finite(p), "vertices are finite");
    } catch (const rt::InputError& e) {
        const std::string message = e.what();
        expect(message.find('\n') == std::string::npos, "an error message is one line");
        expect(message.rfind(scene_file.string() + ": shapes[0]", 0) == 0,
               "an error message names the place");
    }
    std::error_code ec;
    fs::remove_all(kFolder, ec);
    return 0;
}
