#include "rt/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>

namespace rt {
namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_sigint(int) {
    if (g_interrupted.exchange(true)) _exit(130);
    const char message[] = "\ninterrupted: finishing the current tiles, then saving the partial image\n";
    [[maybe_unused]] auto written = write(STDERR_FILENO, message, sizeof message - 1);
}

}  // namespace

void install_interrupt_handler() { std::signal(SIGINT, on_sigint); }
bool interrupt_requested() { return g_interrupted.load(std::memory_order_relaxed); }
void set_interrupt_requested(bool requested) { g_interrupted.store(requested); }

}  // namespace rt
