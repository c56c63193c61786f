// libFuzzer target for the course's PLY reader alone (common/rt/io/ply_parser.cpp): any bytes either give a
// mesh that keeps the reader's promises (every coordinate finite and within the limit, normals and texture
// coordinates one per vertex or none, every face of at least 3 vertices whose indices are in range) or an
// InputError of one line that names its place: "line L: " with L a line of the input, "element NAME I " or
// "byte offset B: " with B inside the input. Anything else is a bug the fuzzer reports.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>

#include "fuzz_promise.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/ply_parser.hpp"

namespace {

constexpr double kLimit = 1e9;

void expect(bool holds, const char* promise) {
    expect_promise(holds, "ply_parser_fuzz", promise);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    std::size_t lines = 1;
    for (const char c : bytes) lines += c == '\n';
    try {
        const rt::PlyMesh mesh = rt::parse_ply(bytes, kLimit);
        for (const rt::Vec3& p : mesh.positions) {
            expect(rt::is_finite(p), "coordinates are finite");
            for (int i = 0; i < 3; ++i)
                expect(std::abs(double(p[i])) <= kLimit * (1 + 1e-6), "coordinates are within the limit");
        }
        expect(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size(),
               "a normal per vertex or none");
        expect(mesh.texture_coordinates.empty() || mesh.texture_coordinates.size() == mesh.positions.size(),
               "texture coordinates per vertex or none");
        for (const rt::Vec3& n : mesh.normals)
            expect(rt::is_finite(n) && glm::dot(n, n) > 0, "normals are finite and not zero");
        for (std::size_t face = 0; face < mesh.face_count(); ++face) {
            const std::span<const std::uint32_t> f = mesh.face(face);
            expect(f.size() >= 3, "a face has at least 3 vertices");
            for (const std::uint32_t i : f) expect(i < mesh.positions.size(), "indices are in range");
        }
    } catch (const rt::InputError& e) {
        const std::string message = e.what();
        expect(message.find('\n') == std::string::npos, "an error message is one line");
        unsigned long line = 0, offset = 0;
        if (std::sscanf(message.c_str(), "line %lu: ", &line) == 1) {
            expect(line >= 1 && line <= lines, "an error's line is in the file");
        } else {
            const std::size_t at = message.find("byte offset ");
            expect(message.starts_with("element ") || at == 0,
                   "an error names a line, an element or a byte offset");
            if (at != std::string::npos &&
                std::sscanf(message.c_str() + at, "byte offset %lu", &offset) == 1) {
                expect(offset <= size, "an error's byte offset is in the file");
            }
        }
    }
    return 0;
}
