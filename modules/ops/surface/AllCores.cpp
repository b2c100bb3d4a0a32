#include "ops/surface/AllCores.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace camwb::ops::surface {

bool forEachOnAllCores(std::size_t count, const std::function<void(std::size_t)>& work, const Progress& progress,
                       double from, double to)
{
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> stop{false};
    const auto worker = [&](bool reports) {
        for (std::size_t i; !stop && (i = next++) < count;) {
            work(i);
            const std::size_t finished = ++done;
            // Only the calling thread reports: a progress callback need not be thread-safe.
            if (reports ? !progress.step(from + (to - from) * double(finished) / double(count)) : progress.cancelled())
                stop = true;
        }
    };
    std::vector<std::thread> pool;
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    for (unsigned i = 1; i < cores && i < count; ++i)
        pool.emplace_back(worker, false);
    worker(true);
    for (std::thread& t : pool)
        t.join();
    return !stop && !progress.cancelled();
}

}  // namespace camwb::ops::surface
