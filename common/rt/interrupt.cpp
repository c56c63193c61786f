#include "rt/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>

namespace rt {
namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the SIGINT handler may only touch lock-free atomics");

// First SIGINT: ask the render loop to stop and say so (write(2) is async-signal-safe, printf is not).
// Second SIGINT: exit at once with 130 (128 + SIGINT), as the shell reports a process killed by Ctrl-C.
extern "C" void on_sigint(int) {
    if (g_interrupted.exchange(true)) _exit(130);
    const char message[] =
        "\ninterrupted: finishing the tiles in progress, then saving the partial image (Ctrl-C again to quit "
        "at once)\n";
    [[maybe_unused]] auto written = write(STDERR_FILENO, message, sizeof message - 1);
}

}  // namespace

void install_interrupt_handler() {
    struct sigaction action {};
    action.sa_handler = on_sigint;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a read or write in progress goes on rather than failing with EINTR
    sigaction(SIGINT, &action, nullptr);
}
bool interrupt_requested() {
    return g_interrupted.load(std::memory_order_relaxed);
}
void set_interrupt_requested(bool requested) {
    g_interrupted.store(requested);
}

}  // namespace rt
