// libFuzzer target for the pbrt-v4 reader: any bytes given as a .pbrt scene either translate into JSON that
// the scene loader reads, or raise an InputError with a one-line message that starts with the file's name
// and its line and column ("fuzz_input.pbrt:3:5: ..."), or with the file's name and ": " for a problem of the
// whole file. Anything else (another exception, a crash, a sanitizer report, a broken promise) is a bug the
// fuzzer reports. Build with the "fuzz" preset; .ci/run runs it with every .pbrt scene of the course as seeds.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "rt/core/errors.hpp"
#include "rt/io/pbrt_reader.hpp"
#include "rt/io/scene_loader.hpp"

namespace {

// Inside the course's scene folder, so that an Include of a seed finds its files.
const std::string kFile = std::string(RT_ASSETS_DIR) + "/scenes/fuzz_input.pbrt";

void expect(bool holds, const char* promise) {
    if (!holds) {
        std::fprintf(stderr, "pbrt_reader_fuzz: a broken promise: %s\n", promise);
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const rt::PbrtTranslation translation = rt::translate_pbrt_text(text, kFile);
        const rt::Scene scene = rt::read_scene(translation.scene, kFile);
        expect(scene.image.width >= 1 && scene.image.height >= 1, "the image has a size");
    } catch (const rt::InputError& e) {
        const std::string message = e.what();
        expect(message.find('\n') == std::string::npos, "an error message is one line");
        expect(message.rfind(kFile + ":", 0) == 0, "an error message starts with the file's name");
    }
    return 0;
}
