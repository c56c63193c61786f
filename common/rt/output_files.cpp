#include "rt/output_files.hpp"

#include <pthread.h>
#include <unistd.h>

#include <csignal>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rt/image_io.hpp"

namespace rt {
namespace fs = std::filesystem;

fs::path with_suffix(const fs::path& png, const std::string& suffix, const std::string& extension) {
    fs::path p = png;
    p.replace_filename(png.stem().string() + suffix + extension);
    return p;
}

void check_finite(const Image& image) {
    std::size_t bad = 0;
    int first_x = -1, first_y = -1;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (is_finite(image.at(x, y))) continue;
            if (bad++ == 0) first_x = x, first_y = y;
        }
    }
    if (bad > 0) {
        throw std::runtime_error("the render has " + std::to_string(bad) +
                                 " pixel(s) NaN or infinite (the first at x " + std::to_string(first_x) +
                                 ", y " + std::to_string(first_y) +
                                 "): a bug in the chapter; nothing written");
    }
}

std::string write_outputs(const Image& image, const fs::path& png, const Film* film) {
    const fs::path pfm = with_suffix(png, "", ".pfm"), film_path = with_suffix(png, "", ".film");
    sigset_t sigint, previous;
    sigemptyset(&sigint);
    sigaddset(&sigint, SIGINT);
    pthread_sigmask(SIG_BLOCK, &sigint, &previous);
    const std::string stage = ".staged-" + std::to_string(::getpid());
    std::vector<std::pair<fs::path, fs::path>> files{{png.string() + stage, png},
                                                     {pfm.string() + stage, pfm}};
    if (film) files.emplace_back(film_path.string() + stage, film_path);
    std::error_code ec;
    try {
        write_png(image, files[0].first);
        write_pfm(image, files[1].first);
        if (film) write_film(*film, files[2].first);
        for (auto it = files.rbegin(); it != files.rend(); ++it) fs::rename(it->first, it->second);
    } catch (const std::exception& e) {
        for (const auto& [staged, final_path] : files) fs::remove(staged, ec);
        pthread_sigmask(SIG_SETMASK, &previous, nullptr);
        // The messages of the writers name the staging file; name the file the user asked for.
        std::string what = e.what();
        for (const auto& [staged, final_path] : files) {
            for (auto at = what.find(staged.string()); at != std::string::npos;
                 at = what.find(staged.string())) {
                what.replace(at, staged.string().size(), final_path.string());
            }
        }
        throw std::runtime_error(what);
    }
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    return film ? png.string() + ", " + pfm.string() + " and " + film_path.string()
                : png.string() + " and " + pfm.string();
}

}  // namespace rt
