#include "rt/live/live_view.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rt/io/effects.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/image_io.hpp"
#include "rt/render/interrupt.hpp"

namespace rt {
namespace {

// The page, common/rt/live/live_page.html, made a string literal by common/CMakeLists.txt.
constexpr const char kLivePage[] =
#include "rt/live/live_page.inc"
    ;

// The picture of an image as write_png makes it, in memory.
std::string png_bytes(const Image& image) {
    char* buffer = nullptr;
    std::size_t size = 0;
    std::FILE* memory = open_memstream(&buffer, &size);
    if (!memory) throw std::runtime_error("live view: cannot open a memory stream");
    const bool encoded = encode_png(image, memory);
    const bool closed = std::fclose(memory) == 0;
    std::string bytes = encoded && closed ? std::string(buffer, size) : std::string();
    std::free(buffer);
    if (bytes.empty()) throw std::runtime_error("live view: cannot encode the PNG");
    return bytes;
}

// Where a render stands, for the page.
struct Snapshot {
    int pass = 0;
    std::string status = "rendering";
    std::uint32_t spp_min = 0;
    double spp_mean = 0;
    std::uint64_t samples = 0;
    double seconds = 0;
    RayCounts rays;
    nlohmann::json errors = nlohmann::json::array();
};

class Session {
public:
    explicit Session(const LiveRun& run) : run_(run) {}

    int serve(int port) {
        LiveServer server(port, kLivePage);
        server_ = &server;
        set_interrupt_phase(InterruptPhase::kLive);
        std::printf("%s: live view on http://127.0.0.1:%d/ (Ctrl-C to stop; nothing is written)\n",
                    run_.chapter.executable, server.port());
        std::fflush(stdout);
        while (!signal_received()) {
            render_once();
            if (signal_received()) break;
            if (render_restart_requested()) continue;
            // Done: wait for a change, or a signal.
            while (!signal_received() && !render_restart_requested()) {
                server.answer_changes([this](const LiveChange& c) { return apply(c); });
                server.wait_for_change(std::chrono::milliseconds(100));
            }
        }
        server.stop();
        std::fprintf(stderr, "%s: live view stopped; nothing written\n", run_.chapter.executable);
        return interrupted_exit_status();
    }

private:
    EffectSet simulated() const { return (run_.needed & run_.chapter.supported).without(switched_off_); }
    bool switchable(Effect e) const {
        return e != Effect::kCameraRays && (run_.needed & run_.chapter.supported).contains(e);
    }

    void render_once() {
        set_render_restart(false);
        ++render_number_;
        RunContext context{run_.scene, run_.settings, simulated()};
        Snapshot snapshot;
        AfterEachPass publish_pass([&](const PassReport& report) {
            ++snapshot.pass;
            take_counts(snapshot, report.image, report.fewest_samples, double(report.samples_held),
                        report.samples, report.seconds, report.rays);
            publish(snapshot, png_bytes(report.image));
            server_->answer_changes([this](const LiveChange& c) { return apply(c); });
        });
        context.settings.observer = &publish_pass;
        publish(snapshot, std::nullopt);
        std::optional<ChapterRun> result;
        try {
            result = run_.render(context);
        } catch (const InputError& e) {
            // The chapter refused what its flags allowed (a combination it checks itself): the last knob
            // change is taken back and the render starts again.
            if (!knob_changed_) throw;
            run_.knobs.undo();
            knob_changed_ = false;
            message_ = std::string("refused: ") + e.what();
            set_render_restart(true);
            return;
        }
        if (interrupt_requested()) return;
        knob_changed_ = false;
        if (!result) {
            snapshot.status = "done: the chapter printed a report instead of an image";
            publish(snapshot, std::nullopt);
            return;
        }
        const RenderResult& r = result->result;
        take_counts(snapshot, r.image, std::uint32_t(std::max(r.samples_per_pixel, 0)),
                    r.sums.empty() ? double(r.samples) : double(r.sums.total_count()), r.samples, r.seconds,
                    r.rays);
        if (result->exact) add_error(snapshot, "the exact image", r.image, *result->exact);
        snapshot.status = "done";
        snapshot.pass = std::max(snapshot.pass, 1);  // a render of one pass
        publish(snapshot, png_bytes(r.image));
    }

    void take_counts(Snapshot& s, const Image& image, std::uint32_t spp_min, double samples_held,
                     std::uint64_t samples, double seconds, const RayCounts& rays) const {
        s.spp_min = spp_min;
        s.spp_mean = samples_held / (double(run_.settings.width) * double(run_.settings.height));
        s.samples = samples;
        s.seconds = seconds;
        s.rays = rays;
        s.errors = nlohmann::json::array();
        if (run_.reference) add_error(s, "the reference", image, *run_.reference);
    }

    static void add_error(Snapshot& s, const char* against, const Image& image, const Image& reference) {
        const ErrorMetrics e = compare(image, reference);
        s.errors.push_back({{"against", against},
                            {"rmse", e.rmse},
                            {"relative_mse", e.relative_mse},
                            {"mean_error", e.mean_error}});
    }

    void publish(const Snapshot& s, std::optional<std::string> png) {
        if (png) ++frame_;
        nlohmann::json rays = nlohmann::json::object();
        for (int k = 0; k < kRayKindCount; ++k)
            rays[std::string(kRayKindNames[std::size_t(k)])] = s.rays.count[std::size_t(k)];
        nlohmann::json knobs = nlohmann::json::array();
        for (const Knob& k : run_.knobs.knobs())
            knobs.push_back({{"name", k.name}, {"help", k.help}, {"choices", k.choices}, {"value", k.value}});
        nlohmann::json effects = nlohmann::json::array();
        for (int i = 0; i < kEffectCount; ++i) {
            const Effect e = Effect(i);
            effects.push_back({{"name", kEffectNames[std::size_t(i)]},
                               {"needed", run_.needed.contains(e)},
                               {"supported", run_.chapter.supported.contains(e)},
                               {"on", simulated().contains(e)},
                               {"switchable", switchable(e)}});
        }
        const double seconds = std::max(s.seconds, 1e-9);
        const nlohmann::json state = {
            {"chapter", run_.chapter.executable},
            {"scene", run_.scene.file},
            {"width", run_.settings.width},
            {"height", run_.settings.height},
            {"render", render_number_},
            {"pass", s.pass},
            {"frame", frame_},
            {"status", s.status},
            {"spp_target", samples_taken(run_.settings).size()},
            {"spp_min", s.spp_min},
            {"spp_mean", s.spp_mean},
            {"samples", s.samples},
            {"seconds", s.seconds},
            {"samples_per_second", double(s.samples) / seconds},
            {"rays", rays},
            {"ray_total", s.rays.total()},
            {"errors", s.errors},
            {"simulated", simulated().to_string()},
            {"knobs", knobs},
            {"effects", effects},
            {"message", message_}};
        // A text that is not UTF-8 (a scene's file name may be any bytes) is shown with U+FFFD in its place.
        server_->publish(std::move(png), state.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    }

    // A change from the page: applied, and the render started again; or refused with the reason.
    std::optional<std::string> apply(const LiveChange& change) {
        if (change.kind == "knob") {
            try {
                run_.knobs.set(change.name, change.value);
            } catch (const InputError& e) {
                return printable(e.what());
            }
            knob_changed_ = true;
        } else if (change.kind == "effect") {
            const std::optional<Effect> effect = effect_from_name(change.name);
            if (!effect) return "no effect named '" + change.name + "'";
            if (!switchable(*effect)) {
                return "effect " + change.name + " cannot be switched here: " +
                       (*effect == Effect::kCameraRays ? std::string("without camera rays there is no image")
                                                       : "it is not simulated by this chapter on this scene");
            }
            if (change.value == "on") {
                switched_off_ = switched_off_.without(EffectSet{*effect});
            } else if (change.value == "off") {
                switched_off_.insert(*effect);
            } else {
                return "effect " + change.name + ": the value must be on or off, got '" + change.value + "'";
            }
        } else {
            return "a change is a knob or an effect, got '" + change.kind + "'";
        }
        message_.clear();
        set_render_restart(true);
        return std::nullopt;
    }

    const LiveRun& run_;
    LiveServer* server_ = nullptr;
    EffectSet switched_off_;
    int render_number_ = 0;
    int frame_ = 0;
    bool knob_changed_ = false;  // since the last render that finished
    std::string message_;
};

}  // namespace

void add_live_flags(CLI::App& app, LiveOptions& options) {
    app.add_flag("--live", options.live,
                 "Serve a live view for a class on http://127.0.0.1:PORT: the image pass by pass, the counters, "
                 "and the knobs and effects switched without restarting; writes no file; Ctrl-C stops it");
    app.add_option("--port", options.port, "With --live: the port (0: any free one, printed)")
        ->check(CLI::Range(0, 65535));
}

int run_live(const LiveRun& run, int port) {
    Session session(run);
    return session.serve(port);
}

}  // namespace rt
