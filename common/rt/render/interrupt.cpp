#include "rt/render/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>

#include "rt/core/errors.hpp"
#include "rt/io/staged_file.hpp"

namespace rt {
namespace {

std::atomic<int> g_signal{0};  // the first signal received, 0 before any
std::atomic<InterruptPhase> g_phase{InterruptPhase::kRendering};
std::atomic<bool> g_restart{false};  // the live view asks the render in progress to stop
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<InterruptPhase>::is_always_lock_free,
              "the signal handler may only touch lock-free atomics");

void say(const char* message, std::size_t size) {
    [[maybe_unused]] auto written = write(STDERR_FILENO, message, size);
}

// A first stopping signal: ask the render loop to stop (or let the files being written finish) and say so
// (write(2) is async-signal-safe, printf is not). A second one, of any kind: remove the staging files, exit.
extern "C" void on_stop(int signal_number) {
    int none = 0;
    if (!g_signal.compare_exchange_strong(none, signal_number)) {
        remove_staged_files_now();
        _exit(128 + signal_number);
    }
    if (g_phase.load() == InterruptPhase::kLive) {
        const char message[] = "\ninterrupted: stopping the live view (it writes nothing)\n";
        say(message, sizeof message - 1);
    } else if (g_phase.load() == InterruptPhase::kReading) {
        const char message[] = "\ninterrupted: stopping before anything is written\n";
        say(message, sizeof message - 1);
    } else if (g_phase.load() == InterruptPhase::kRendering) {
        const char message[] =
            "\ninterrupted: stopping the samples in progress, then saving the partial image (interrupt again "
            "to quit at once, saving nothing)\n";
        say(message, sizeof message - 1);
    } else {
        const char message[] =
            "\ninterrupted: finishing the files being written (interrupt again to quit at once, writing "
            "nothing)\n";
        say(message, sizeof message - 1);
    }
}

// A signal that ends the process at once: the staging files go first.
extern "C" void on_quit(int signal_number) {
    remove_staged_files_now();
    _exit(128 + signal_number);
}

void handle(int signal_number, void (*handler)(int)) {
    struct sigaction action {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a read or write in progress goes on rather than failing with EINTR
    sigaction(signal_number, &action, nullptr);
}

}  // namespace

void install_interrupt_handler() {
    for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGXCPU}) handle(s, on_stop);
    for (const int s : {SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM}) handle(s, on_quit);
    for (const int s : {SIGPIPE, SIGXFSZ}) handle(s, SIG_IGN);
}
void set_interrupt_phase(InterruptPhase phase) {
    g_phase.store(phase);
}
bool interrupt_requested() {
    return signal_received() || g_restart.load(std::memory_order_relaxed);
}
bool signal_received() {
    return g_signal.load(std::memory_order_relaxed) != 0;
}
void set_render_restart(bool restart) {
    g_restart.store(restart);
}
bool render_restart_requested() {
    return g_restart.load();
}
int interrupted_exit_status() {
    const int s = g_signal.load();
    return 128 + (s != 0 ? s : SIGINT);
}
bool stop_before_writing(const char* program) {
    if (signal_received()) {
        std::fprintf(stderr, "%s: interrupted; nothing written\n", program);
        return true;
    }
    set_interrupt_phase(InterruptPhase::kWriting);
    return false;
}
int status_after_writing(const char* program, const char* what) {
    if (!signal_received()) return kExitOk;
    std::fprintf(stderr, "%s: interrupted while writing; %s was written all the same\n", program, what);
    return interrupted_exit_status();
}
void set_interrupt_requested(bool requested) {
    g_signal.store(requested ? SIGINT : 0);
}

}  // namespace rt
