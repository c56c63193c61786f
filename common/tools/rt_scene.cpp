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

int main(int argc, char** argv) {
    CLI::App app("Translates a pbrt-v4 scene into the course's scene JSON and prints it", "rt_scene");
    std::string file;
    app.add_option("--to-json", file, "The pbrt-v4 scene file")->required();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return e.get_exit_code() == 0 ? app.exit(e) : (app.exit(e), 2);
    }
    try {
        if (!rt::is_pbrt_file(file)) throw rt::InputError(rt::shown(file) + ": must be a pbrt-v4 scene (a name ending in .pbrt)");
        const rt::PbrtTranslation translation = rt::translate_pbrt(file);
        rt::read_scene(translation.scene, file);  // what a chapter would refuse, refused here too
        std::printf("%s\n", translation.scene.dump(2).c_str());
        for (const std::string& note : translation.notes) std::fprintf(stderr, "rt_scene: ignored: %s\n", note.c_str());
    } catch (const rt::InputError& e) {
        std::fprintf(stderr, "rt_scene: %s\n", e.what());
        return 2;
    }
    return 0;
}
