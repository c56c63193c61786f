// libFuzzer target for the course's OBJ reader alone (common/rt/io/obj_parser.cpp): any bytes either give a mesh
// that keeps the reader's promises (every coordinate finite and within the limit, every face of at least 3
// vertices whose indices are in range, on a line of the file) or an InputError of one line that starts
// "line L, column C: " with L a line of the input. Anything else is a bug the fuzzer reports.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fuzz_promise.hpp"
#include "rt/core/errors.hpp"
#include "rt/io/obj_parser.hpp"

namespace {

constexpr double kLimit = 1e9;

void expect(bool holds, const char* promise) {
    expect_promise(holds, "obj_parser_fuzz", promise);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::size_t lines = 1;
    for (const char c : text) lines += c == '\n';
    try {
        const rt::ObjMesh mesh = rt::parse_obj(text, kLimit);
        for (const rt::Vec3& p : mesh.positions) {
            expect(rt::is_finite(p), "coordinates are finite");
            for (int i = 0; i < 3; ++i) expect(std::abs(double(p[i])) <= kLimit * (1 + 1e-6), "coordinates are within the limit");
        }
        for (const rt::ObjFace& f : mesh.faces) {
            expect(f.vertices.size() >= 3, "a face has at least 3 vertices");
            expect(f.line >= 1 && f.line <= lines, "a face's line is a line of the file");
            for (const std::uint32_t i : f.vertices) expect(i < mesh.positions.size(), "indices are in range");
        }
    } catch (const rt::InputError& e) {
        const std::string message = e.what();
        expect(message.find('\n') == std::string::npos, "an error message is one line");
        unsigned long line = 0, column = 0;
        expect(std::sscanf(message.c_str(), "line %lu, column %lu: ", &line, &column) == 2,
               "an error message starts with its line and column");
        expect(line >= 1 && line <= lines && column >= 1, "an error's line and column are in the file");
    }
    return 0;
}
