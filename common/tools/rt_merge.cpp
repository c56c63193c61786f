// rt_merge --out x.png PIECES.film...: adds the films of a render's pieces (chNN_name --samples A:B --out
// p.png writes p.film) into the image of the whole render, bit for bit the image of one run of --spp N. The
// pieces must be of one render and together take samples 0:N exactly once; anything else exits with 2 and
// one line naming the offending piece. Writes x.png, x.pfm and x.film (a film of 0:N), none of them a piece;
// --out x.exr writes x.exr (half floats, or floats with --exr-float), x.png and x.film.
// Signals as the chapters take them (interrupt.hpp); the texts a film holds are printed escaped.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/output_files.hpp"
#include "rt/io/run_files.hpp"
#include "rt/render/interrupt.hpp"
#include "rt/run/film_merge.hpp"

namespace {

namespace fs = std::filesystem;

int merge(int argc, char** argv) {
    rt::install_interrupt_handler();
    rt::set_interrupt_phase(rt::InterruptPhase::kReading);
    CLI::App app("Adds the films of a render's pieces (--samples A:B) into the image of the whole",
                 "rt_merge");
    std::string out;
    bool exr_float = false;
    std::vector<std::string> pieces;
    app.add_option("--out", out,
                   "Output image: x.png (the PFM beside it) or x.exr (the PNG beside it); the film of the "
                   "whole goes beside them")
        ->required();
    app.add_flag("--exr-float", exr_float,
                 "With --out x.exr: floats (32 bits) instead of half floats (16 bits)");
    app.add_option("pieces", pieces, "The pieces' films")->required();
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw rt::InputError(std::string("usage: ") + e.what() + " (see --help)");
    }
    const rt::ImageOutput image_out = rt::image_output(out, exr_float);
    std::vector<rt::RunFile> inputs;
    for (const std::string& piece : pieces) inputs.push_back({"", "the piece", piece});
    rt::check_outputs({{"--out", "the merged image", image_out.picture()},
                       {"--out", "the merged radiance", image_out.radiance()},
                       {"--out", "the merged film", rt::with_suffix(image_out.path, "", ".film")}},
                      inputs);
    std::vector<rt::FilmPiece> films;
    for (const std::string& piece : pieces) {
        if (rt::signal_received()) break;
        films.push_back({piece, rt::read_film(piece)});
    }
    // A signal stops the reading: the pieces left unread are missing by no fault of theirs.
    if (rt::signal_received() && rt::stop_before_writing("rt_merge")) return rt::interrupted_exit_status();
    const rt::Film whole = rt::merge_films(std::move(films));
    const rt::Image image = whole.sums.mean_image();
    rt::check_finite(image);
    if (rt::stop_before_writing("rt_merge")) return rt::interrupted_exit_status();
    const std::string written = rt::write_outputs(image, image_out, &whole);
    const rt::FilmIdentity& id = whole.identity;
    std::printf("rt_merge: %zu pieces of %s on %s, %dx%d, samples 0:%d, seed %llu: wrote %s\n", pieces.size(),
                rt::printable(id.chapter).c_str(), rt::printable(id.scene).c_str(), id.width, id.height,
                id.samples_per_pixel, static_cast<unsigned long long>(id.seed), written.c_str());
    return rt::status_after_writing("rt_merge", "the merged image");
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return merge(argc, argv);
    } catch (const rt::InputError& e) {
        std::fprintf(stderr, "rt_merge: %s\n", rt::printable(e.what()).c_str());
        return rt::kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rt_merge: failed: %s\n", rt::printable(e.what()).c_str());
        return rt::kExitFailure;
    }
}
