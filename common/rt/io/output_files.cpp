#include "rt/io/output_files.hpp"

#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/exr_file.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/staged_file.hpp"

namespace rt {
namespace fs = std::filesystem;

fs::path with_suffix(const fs::path& png, const std::string& suffix, const std::string& extension) {
    fs::path p = png;
    p.replace_filename(png.stem().string() + suffix + extension);
    return p;
}

ImageOutput image_output(const fs::path& out, bool exr_float) {
    const std::string name = out.filename().string();
    const bool exr = name.ends_with(".exr");
    if ((!exr && !name.ends_with(".png")) || name.size() == 4) {
        throw InputError(
            "--out: must name a file ending in .png or .exr, with a name before the extension, got " +
            shown(out));
    }
    if (exr_float && !exr) throw InputError("--exr-float: is used only with --out naming a .exr file");
    if (exr && !has_openexr()) {
        throw InputError(
            "--out: " + shown(out) +
            ": OpenEXR files are not written by this build (install libopenexr-dev and configure "
            "again); name a .png, and its radiance goes beside it as a .pfm");
    }
    return {out, !exr        ? RadianceFormat::kPfm
                 : exr_float ? RadianceFormat::kExrFloat
                             : RadianceFormat::kExrHalf};
}

fs::path ImageOutput::picture(const std::string& suffix) const {
    return with_suffix(path, suffix, ".png");
}

fs::path ImageOutput::radiance(const std::string& suffix) const {
    return with_suffix(path, suffix, format == RadianceFormat::kPfm ? ".pfm" : ".exr");
}

ImageOutput ImageOutput::partial() const {
    return {with_suffix(path, ".partial", path.extension().string()), format};
}

std::vector<RunFile> image_outputs(const ImageOutput& out, bool film,
                                   const std::vector<std::string>& extra_images) {
    std::vector<RunFile> files;
    for (const std::string partial : {"", ".partial"}) {
        const std::string of = partial.empty() ? "the " : "the partial ";
        files.push_back({"--out", of + "image", out.picture(partial)});
        files.push_back({"--out", of + "radiance", out.radiance(partial)});
        // The file --out named first, so that a message about both names it.
        if (out.format != RadianceFormat::kPfm) std::swap(files[files.size() - 2], files.back());
        if (film || !partial.empty())
            files.push_back({"--out", of + "film", with_suffix(out.path, partial, ".film")});
        for (const std::string& suffix : extra_images)
            files.push_back({"--out", of + suffix.substr(1) + " image", out.radiance(partial + suffix)});
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

namespace {

// The radiance's bytes, as a PFM or an EXR, into `file`; false when a write failed.
bool encode_radiance(const Image& image, RadianceFormat format, std::FILE* file) {
    if (format == RadianceFormat::kPfm) return encode_pfm(image, file);
    return encode_exr(image, format == RadianceFormat::kExrHalf ? ExrChannels::kHalf : ExrChannels::kFloat,
                      file);
}

// The name of a radiance file for the summary, saying how many channels a half-float file holds as ±65504.
std::string radiance_written(const fs::path& path, const Image& image, RadianceFormat format) {
    const std::size_t beyond = format == RadianceFormat::kExrHalf ? beyond_half_range(image) : 0;
    if (beyond == 0) return shown(path);
    return shown(path) + " (" + std::to_string(beyond) +
           " channel value(s) beyond a half float's range held as +-65504; --exr-float keeps them)";
}

}  // namespace

std::string write_outputs(const Image& image, const ImageOutput& out, const Film* film,
                          const std::vector<ExtraImage>& extra) {
    const fs::path png = out.picture(), radiance = out.radiance(),
                   film_path = with_suffix(out.path, "", ".film");
    for (const ExtraImage& e : extra) check_finite(e.image);
    // Every file is written whole under its staging name first; then the renames, all or none.
    StagedFile png_file(png), radiance_file(radiance);
    write_staged(png_file, [&](std::FILE* file) { return encode_png(image, file); });
    write_staged(radiance_file, [&](std::FILE* file) { return encode_radiance(image, out.format, file); });
    std::vector<StagedFile*> files{&radiance_file, &png_file};
    const std::string radiance_name = radiance_written(radiance, image, out.format);
    std::vector<std::string> names = out.format == RadianceFormat::kPfm
                                         ? std::vector<std::string>{shown(png), radiance_name}
                                         : std::vector<std::string>{radiance_name, shown(png)};
    std::vector<std::unique_ptr<StagedFile>> extra_files;
    for (const ExtraImage& e : extra) {
        extra_files.push_back(std::make_unique<StagedFile>(out.radiance(e.suffix)));
        write_staged(*extra_files.back(),
                     [&](std::FILE* file) { return encode_radiance(e.image, out.format, file); });
        files.insert(files.begin(), extra_files.back().get());
        names.push_back(radiance_written(out.radiance(e.suffix), e.image, out.format));
    }
    std::optional<StagedFile> film_file;
    if (film) {
        film_file.emplace(film_path);
        write_staged(*film_file, [&](std::FILE* file) { return encode_film(*film, file); });
        files.insert(files.begin(), &*film_file);
        names.push_back(shown(film_path));
    }
    commit_together(files);
    std::string written;
    for (std::size_t i = 0; i < names.size(); ++i)
        written += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return written;
}

}  // namespace rt
