// sampler_view [--port P]: a sampler you can see. Serves http://127.0.0.1:P/, a page on which a student picks
// any direction sampler of chapters 04, 06, 07 and 09 (tests/support/sampler_registry.hpp), sets its
// parameters and sees its histogram over the sphere's (cos θ, φ) beside the density its pdf predicts, the
// chi-square verdict of the tests' harness and the cells that fail, as Nori's warptest shows them. The
// samplers are the chapters' own code: in the student edition, the student's. Runs until Ctrl-C (exit 130);
// writes nothing. A bad flag, a port in use or a build without cpp-httplib: exit 2 and one line.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <thread>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/render/interrupt.hpp"
#include "rt/run/strict_flags.hpp"
#include "sampler_report.hpp"

namespace {

constexpr const char* kPage =
#include "sampler_view/sampler_page.inc"
    ;

int serve(int argc, char** argv) {
    int port = rt::kDefaultLivePort + 1;
    CLI::App app{
        "sampler_view: the course's samplers, their histograms, densities and chi-square verdicts, "
        "in a browser"};
    app.add_option("--port", port, "The port on 127.0.0.1 (0: any free one, printed)")
        ->check(CLI::Range(0, 65535))
        ->capture_default_str();
    rt::make_values_strict(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw rt::InputError(std::string("usage: ") + e.what() + " (see --help)");
    }
    rt::install_interrupt_handler();
    const auto registry = rt::test::sampler_registry();
    rt::LiveServer server(
        port, kPage,
        {{"/samplers", [&](const rt::LiveQuery&) { return rt::test::samplers_answer(registry); }},
         {"/sample", [&](const rt::LiveQuery& query) { return rt::test::sample_answer(registry, query); }}});
    rt::set_interrupt_phase(rt::InterruptPhase::kLive);
    std::printf("sampler_view: sampler view on http://127.0.0.1:%d/ (Ctrl-C to stop; nothing is written)\n",
                server.port());
    std::fflush(stdout);
    while (!rt::signal_received()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    server.stop();
    std::fprintf(stderr, "sampler_view: stopped\n");
    return rt::interrupted_exit_status();
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return serve(argc, argv);
    } catch (const rt::InputError& e) {
        std::fprintf(stderr, "sampler_view: %s\n", rt::printable(e.what()).c_str());
        return rt::kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sampler_view: %s\n", rt::printable(e.what()).c_str());
        return rt::kExitFailure;
    }
}
