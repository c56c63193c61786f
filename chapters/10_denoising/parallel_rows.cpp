#include "parallel_rows.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rt {

void for_each_row(int height, int threads, const std::function<void(int)>& row) {
    const int count =
        std::clamp(threads > 0 ? threads : int(std::thread::hardware_concurrency()), 1, std::max(height, 1));
    std::atomic<int> next{0};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto work = [&] {
        try {
            for (int y = next++; y < height; y = next++) row(y);
        } catch (...) {
            const std::lock_guard lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            next = height;
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < count; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace rt
