// exr_to_pfm IN.exr OUT.pfm: an OpenEXR image (linear RGB, as Tungsten's references) as a colour PFM, which
// tests/tools/bitterli_check.py reads. Read by the environment images' reader, so only where the course was
// built with OpenEXR; exits 2 with one line otherwise, or when IN is not an image it reads.
#include <cstdio>

#include "rt/core/errors.hpp"
#include "rt/io/environment_image.hpp"
#include "rt/io/image_io.hpp"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: exr_to_pfm IN.exr OUT.pfm\n");
        return 2;
    }
    try {
        rt::write_pfm(rt::read_environment_image(argv[1]), argv[2]);
    } catch (const rt::InputError& e) {
        std::fprintf(stderr, "exr_to_pfm: %s\n", e.what());
        return 2;
    }
    return 0;
}
