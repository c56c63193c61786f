#include "rt/render/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rt {

int thread_count(int threads) {
    return threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

bool parallel_for(std::size_t count, const ParallelOptions& options,
                  const std::function<void(std::size_t item, int thread)>& work) {
    const int threads = int(std::clamp<std::size_t>(std::size_t(thread_count(options.threads)), 1,
                                                    std::max<std::size_t>(count, 1)));
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stopped{false};
    std::exception_ptr failure;  // the first exception an item threw, on any thread
    std::mutex failure_mutex;
    std::atomic<bool> failed{false};
    std::atomic<int> workers_running{threads};
    auto worker = [&](int thread) {
        try {
            for (std::size_t item = next++; item < count && !failed; item = next++) {
                if (options.stop && options.stop()) {
                    stopped = true;
                    break;
                }
                work(item, thread);
            }
        } catch (...) {
            // An exception cannot cross a thread: keep the first, stop the others, rethrow it below.
            const std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            failed = true;
        }
        --workers_running;
    };

    std::vector<std::thread> pool;
    const int first_pooled = options.show_progress ? 0 : 1;
    for (int t = first_pooled; t < threads; ++t) pool.emplace_back(worker, t);
    if (options.show_progress) {
        while (workers_running.load() > 0) {
            options.show_progress();
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    } else {
        worker(0);
    }
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    return !stopped;
}

}  // namespace rt
