// rt_compare A B [--out d.png] [--tolerance L] [--max-differing F]: two renders (PFM, EXR or PNG) side by
// side. Prints the error metrics of error_metrics.hpp when both are radiance (PFM or EXR), and always how the
// two pictures (as a PNG shows them: tone-mapped, sRGB, 8 bits) differ and where (picture_compare.hpp). With
// --out, writes A | B | the error in false colour | its colour bar, one PNG (or a half-float EXR of it).
// Exit status 0 when at most a fraction F of the pixels differ by more than L levels (default 0: none), 1
// when more do (like cmp), 2 on bad input (an --out that is A or B among it; a broken PFM, EXR or PNG).
// Signals as the chapters take them (interrupt.hpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/exr_file.hpp"
#include "rt/io/false_colour.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/picture_compare.hpp"
#include "rt/io/run_files.hpp"
#include "rt/render/interrupt.hpp"

namespace {

namespace fs = std::filesystem;

// A file read as linear radiance when it is a PFM or an EXR, or as the picture a PNG holds.
struct Input {
    std::optional<rt::Image> radiance;
    rt::Picture picture;
};

Input read_input(const std::string& name) {
    const fs::path path = name;
    if (path.extension() == ".pfm" || path.extension() == ".exr") {
        rt::Image image = rt::read_radiance(path);
        rt::Picture picture = rt::to_picture(image);
        return {std::move(image), std::move(picture)};
    }
    if (path.extension() == ".png") return {std::nullopt, rt::read_png(path)};
    throw rt::InputError(rt::shown(path) + ": must end in .pfm, .exr or .png");
}

// A | B | the per-pixel error (the largest channel's, in radiance for two PFMs, else in levels of 255) scaled
// so that `scale` is white | a colour bar from 0 (bottom) to `scale` (top). 4-pixel grey gaps between.
void write_side_by_side(const Input& a, const Input& b, const fs::path& out, double& scale) {
    const int w = a.picture.width, h = a.picture.height, gap = 4, bar = 16;
    std::vector<double> error(std::size_t(w) * std::size_t(h), 0);
    const bool linear = a.radiance && b.radiance;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            double e = 0;
            for (int c = 0; c < 3; ++c) {
                e = std::max(e, linear ? std::abs(double(a.radiance->at(x, y)[c]) - double(b.radiance->at(x, y)[c]))
                                       : std::abs(double(a.picture.at(x, y, c)) - double(b.picture.at(x, y, c))));
            }
            error[std::size_t(y) * std::size_t(w) + std::size_t(x)] = e;
        }
    }
    scale = *std::max_element(error.begin(), error.end());
    const int width = 3 * w + 3 * gap + bar;
    rt::Image canvas(width, h);
    for (rt::Color& c : canvas.pixels()) c = rt::Color(rt::Real(0.2));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const auto pixel = [&](const rt::Picture& p) {
                return rt::linear_of_display({p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2)});
            };
            canvas.at(x, y) = pixel(a.picture);
            canvas.at(w + gap + x, y) = pixel(b.picture);
            const double e = error[std::size_t(y) * std::size_t(w) + std::size_t(x)];
            canvas.at(2 * (w + gap) + x, y) = rt::linear_of_display(rt::false_colour(scale > 0 ? e / scale : 0));
        }
    }
    rt::paint_colour_bar(canvas, 3 * (w + gap), bar);
    if (out.extension() == ".exr")
        rt::write_exr(canvas, out, rt::ExrChannels::kHalf);
    else
        rt::write_png(canvas, out);
}

int compare(int argc, char** argv) {
    rt::install_interrupt_handler();
    rt::set_interrupt_phase(rt::InterruptPhase::kReading);
    CLI::App app(
        "Compares two renders (PFM, EXR or PNG): metrics, where their pictures differ, and A | B | error",
        "rt_compare");
    std::string a_name, b_name, out;
    int tolerance = 0;
    double max_differing = 0;
    app.add_option("a", a_name, "The image (PFM, EXR or PNG)")->required();
    app.add_option("b", b_name, "The reference (PFM, EXR or PNG)")->required();
    app.add_option("--out", out,
                   "Writes A | B | false-colour error | colour bar here (PNG, or a half-float EXR)");
    app.add_option("--tolerance", tolerance, "Levels (of 255) a channel may differ by")
        ->check(CLI::Range(0, 255))->capture_default_str();
    app.add_option("--max-differing", max_differing, "Fraction of the pixels that may differ (exit 1 beyond)")
        ->check(CLI::Range(0.0, 1.0))->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw rt::InputError(std::string("usage: ") + e.what() + " (see --help)");
    }
    if (!out.empty()) {
        const std::string extension = fs::path(out).extension().string();
        if (extension != ".png" && extension != ".exr")
            throw rt::InputError("--out: must end in .png or .exr, got " + rt::shown(out));
        if (extension == ".exr" && !rt::has_openexr())
            throw rt::InputError("--out: " + rt::shown(out) +
                                 ": OpenEXR files are not written by this build; name a .png");
        rt::check_outputs({{"--out", "the comparison picture", out}},
                          {{"", "image A", a_name}, {"", "image B", b_name}});
    }
    const Input a = read_input(a_name), b = read_input(b_name);
    if (rt::stop_before_writing("rt_compare")) return rt::interrupted_exit_status();
    const rt::PictureDifference d = rt::compare_pictures(a.picture, b.picture, tolerance);
    std::printf("rt_compare: %s against %s, %dx%d\n", rt::shown(a_name).c_str(), rt::shown(b_name).c_str(),
                d.width, d.height);
    if (a.radiance && b.radiance) {
        const rt::ErrorMetrics m = rt::compare(*a.radiance, *b.radiance);
        std::printf("  radiance: RMSE %.6g, relative MSE %.6g, mean error %+.6g\n", m.rmse, m.relative_mse,
                    m.mean_error);
    }
    std::printf("  pictures (as their PNGs show them):\n%s", rt::describe(d, "    ").c_str());
    if (!out.empty()) {
        double scale = 0;
        write_side_by_side(a, b, out, scale);
        std::printf(
            "  wrote %s: A | B | error (largest channel) | colour bar from 0 (bottom, black) to %.6g%s "
            "(top, white)\n",
            rt::shown(out).c_str(), scale, a.radiance && b.radiance ? "" : " levels");
    }
    const bool agree = d.fraction() <= max_differing;
    std::printf("  %s\n", agree ? "agree" : "DIFFER");
    if (const int status = rt::status_after_writing("rt_compare", "the picture"); status != rt::kExitOk)
        return status;
    return agree ? rt::kExitOk : rt::kExitFailure;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return compare(argc, argv);
    } catch (const rt::InputError& e) {
        std::fprintf(stderr, "rt_compare: %s\n", rt::printable(e.what()).c_str());
        return rt::kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rt_compare: %s\n", rt::printable(e.what()).c_str());
        return rt::kExitFailure;
    }
}
