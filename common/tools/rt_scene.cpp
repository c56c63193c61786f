// rt_scene --to-json FILE.pbrt: prints the course's scene JSON that a pbrt-v4 scene translates into (the
// JSON that every chapter renders when given the .pbrt file), so a student can read what the reader
// understood. The notes on what the course ignores go to standard error. Exit status 2 on bad input, with
// the reader's one located line.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/pbrt_reader.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/run/strict_flags.hpp"

namespace {

bool all_scalars(const nlohmann::json& array) {
    for (const auto& element : array) {
        if (element.is_structured()) return false;
    }
    return true;
}

// The JSON as a person writes it: objects indented, a vector or colour ([x, y, z]) on one line, and a list
// of them one per line.
void print(const nlohmann::json& value, int indent) {
    const std::string inner(std::size_t(indent + 2), ' '), outer(std::size_t(indent), ' ');
    if (value.is_object() && !value.empty()) {
        std::printf("{");
        const char* separator = "\n";
        for (const auto& [key, element] : value.items()) {
            std::printf("%s%s%s: ", separator, inner.c_str(), nlohmann::json(key).dump().c_str());
            print(element, indent + 2);
            separator = ",\n";
        }
        std::printf("\n%s}", outer.c_str());
    } else if (value.is_array() && !value.empty() && !all_scalars(value)) {
        std::printf("[");
        for (std::size_t i = 0; i < value.size(); ++i) {
            std::printf("%s\n%s", i ? "," : "", inner.c_str());
            print(value[i], indent + 2);
        }
        std::printf("\n%s]", outer.c_str());
    } else {
        std::string text = value.dump();
        for (std::size_t at = text.find(','); at != std::string::npos; at = text.find(',', at + 2)) {
            text.insert(at + 1, " ");
        }
        std::printf("%s", text.c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Translates a pbrt-v4 scene into the course's scene JSON and prints it", "rt_scene");
    std::string file;
    app.add_option("--to-json", file, "The pbrt-v4 scene file")->required();
    if (const auto stop = rt::read_flags(app, argc, argv)) return *stop;
    try {
        if (!rt::is_pbrt_file(file)) throw rt::InputError(rt::shown(file) + ": must be a pbrt-v4 scene (a name ending in .pbrt)");
        const rt::PbrtTranslation translation = rt::translate_pbrt(file);
        rt::read_scene(translation.scene, file);  // what a chapter would refuse, refused here too
        print(translation.scene, 0);
        std::printf("\n");
        for (const std::string& note : translation.notes) std::fprintf(stderr, "rt_scene: ignored: %s\n", note.c_str());
    } catch (const rt::InputError& e) {
        std::fprintf(stderr, "rt_scene: %s\n", e.what());
        return 2;
    }
    return 0;
}
