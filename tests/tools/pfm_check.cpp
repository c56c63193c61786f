// pfm_check A.pfm [B.pfm]: exits 0 when every pixel of A is finite (and, given B, when B is the same image
// bit for bit), else 1 with one line saying what differs. Prints "WxH mean M" for A. Used by tests/cli.
#include <cstdio>
#include <cstring>
#include <exception>

#include "rt/io/image_io.hpp"

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: pfm_check A.pfm [B.pfm]\n");
        return 2;
    }
    try {
        // read_pfm refuses a file with a NaN or infinite pixel, naming the pixel.
        const rt::Image a = rt::read_pfm(argv[1]);
        std::printf("%dx%d mean %.6g\n", a.width(), a.height(), a.mean());
        if (argc == 3) {
            const rt::Image b = rt::read_pfm(argv[2]);
            if (a.width() != b.width() || a.height() != b.height()) {
                std::fprintf(stderr, "%s and %s differ in size\n", argv[1], argv[2]);
                return 1;
            }
            for (std::size_t i = 0; i < a.pixel_count(); ++i) {
                // Bit for bit: memcmp, so that even -0 against +0 counts as a difference.
                if (std::memcmp(&a.pixels()[i], &b.pixels()[i], sizeof(rt::Color)) != 0) {
                    std::fprintf(stderr, "%s and %s differ first at pixel %zu (x %d, y %d)\n", argv[1],
                                 argv[2], i, int(i % std::size_t(a.width())),
                                 int(i / std::size_t(a.width())));
                    return 1;
                }
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
