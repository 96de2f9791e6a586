#pragma once
// A loop split over threads in chunks of consecutive items. Each chunk writes its own results,
// which the caller joins in chunk order: the output is the same for every thread count.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace sdfwb {

// The threads a parallel loop uses: $SDFWB_THREADS when it holds a number >= 1, else the
// hardware's (at least 1).
unsigned workerThreads();

// How many chunks to cut `count` items into: about four a thread, none under `minimum` items.
inline std::size_t chunkCount(std::size_t count, std::size_t minimum) {
    const std::size_t most = std::max<std::size_t>(1, count / std::max<std::size_t>(1, minimum));
    return std::min<std::size_t>(most, std::size_t(workerThreads()) * 4);
}

// Calls work(chunk, begin, end) for each of `chunks` consecutive ranges that cover [0, count),
// on up to workerThreads() threads (the caller's among them), and returns when all are done.
// `work` must not throw.
template <class Work> void forEachChunk(std::size_t count, std::size_t chunks, Work&& work) {
    chunks = std::max<std::size_t>(1, std::min(chunks, std::max<std::size_t>(1, count)));
    std::atomic<std::size_t> next{0};
    auto run = [&] {
        for (std::size_t c = next++; c < chunks; c = next++) work(c, count * c / chunks, count * (c + 1) / chunks);
    };
    const std::size_t helpers = std::min<std::size_t>(chunks, workerThreads()) - 1;
    std::vector<std::thread> threads;
    threads.reserve(helpers);
    for (std::size_t t = 0; t < helpers; ++t) threads.emplace_back(run);
    run();
    for (std::thread& thread : threads) thread.join();
}

} // namespace sdfwb
