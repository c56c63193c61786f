// The course's one parallel engine: items [0, count) handed out in order from a shared counter to a pool of
// threads. Every pass of every chapter runs on it: the render loop's tiles, chapter 08's chunks of light
// paths, chapter 10's filter rows and chapter 11's GPU bands. Which thread runs an item is chance, so an item
// must give the same result on any thread (its own random streams, its own output): what the caller makes of
// the items is then the same bits for any thread count.
#pragma once

#include <cstddef>
#include <functional>

namespace rt {

struct ParallelOptions {
    int threads = 0;  // 0: one per core; never more than the items
    // Asked before each item starts: once true, no further item starts (an interrupt: interrupt_requested).
    // None: every item runs.
    bool (*stop)() = nullptr;
    // Called about every 0.1 s by the calling thread while the items run on the others (a progress bar).
    // None: the calling thread runs items too, so with one thread every item runs on the calling thread (as
    // an OpenGL context needs).
    std::function<void()> show_progress = nullptr;
};

// The threads a run of `threads` uses (0: one per core, at least one).
int thread_count(int threads);

// Calls work(item, thread) once for every item in [0, count), `thread` being the worker's index in
// [0, thread_count(options.threads)), until options.stop says to stop. If work throws, no further item
// starts, every thread finishes the item it is on, and the first exception is rethrown once all have joined.
// Returns whether every item ran (false: stopped).
bool parallel_for(std::size_t count, const ParallelOptions& options,
                  const std::function<void(std::size_t item, int thread)>& work);

}  // namespace rt
