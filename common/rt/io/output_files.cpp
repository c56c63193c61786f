#include "rt/io/output_files.hpp"

#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "rt/core/printable.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/staged_file.hpp"

namespace rt {
namespace fs = std::filesystem;

fs::path with_suffix(const fs::path& png, const std::string& suffix, const std::string& extension) {
    fs::path p = png;
    p.replace_filename(png.stem().string() + suffix + extension);
    return p;
}

std::vector<RunFile> image_outputs(const fs::path& png, bool film,
                                   const std::vector<std::string>& extra_images) {
    std::vector<RunFile> files;
    for (const std::string partial : {"", ".partial"}) {
        const std::string of = partial.empty() ? "the " : "the partial ";
        files.push_back({"--out", of + "image", with_suffix(png, partial, ".png")});
        files.push_back({"--out", of + "radiance", with_suffix(png, partial, ".pfm")});
        if (film || !partial.empty())
            files.push_back({"--out", of + "film", with_suffix(png, partial, ".film")});
        for (const std::string& suffix : extra_images)
            files.push_back(
                {"--out", of + suffix.substr(1) + " image", with_suffix(png, partial + suffix, ".pfm")});
    }
    return files;
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

std::string write_outputs(const Image& image, const fs::path& png, const Film* film,
                          const std::vector<ExtraImage>& extra) {
    const fs::path pfm = with_suffix(png, "", ".pfm"), film_path = with_suffix(png, "", ".film");
    for (const ExtraImage& e : extra) check_finite(e.image);
    // Every file is written whole under its staging name first; then the renames, all or none.
    StagedFile png_file(png), pfm_file(pfm);
    write_staged(png_file, [&](std::FILE* file) { return encode_png(image, file); });
    write_staged(pfm_file, [&](std::FILE* file) { return encode_pfm(image, file); });
    std::vector<StagedFile*> files{&pfm_file, &png_file};
    std::vector<fs::path> names{png, pfm};
    std::vector<std::unique_ptr<StagedFile>> extra_files;
    for (const ExtraImage& e : extra) {
        names.push_back(with_suffix(png, e.suffix, ".pfm"));
        extra_files.push_back(std::make_unique<StagedFile>(names.back()));
        write_staged(*extra_files.back(), [&](std::FILE* file) { return encode_pfm(e.image, file); });
        files.insert(files.begin(), extra_files.back().get());
    }
    std::optional<StagedFile> film_file;
    if (film) {
        film_file.emplace(film_path);
        write_staged(*film_file, [&](std::FILE* file) { return encode_film(*film, file); });
        files.insert(files.begin(), &*film_file);
        names.push_back(film_path);
    }
    commit_together(files);
    std::string written;
    for (std::size_t i = 0; i < names.size(); ++i)
        written += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + shown(names[i]);
    return written;
}

}  // namespace rt
