// Memory about to be written whole, faulted in with one system call instead of one fault per
// 4 KiB page (Linux's MADV_POPULATE_WRITE). The simulator's moves, motion plan and height field
// are megabytes written at once: faulted in so (and the moves' reservation made exact), the
// 20,000-block benchmark simulation went from 0.101 to 0.087 s. Only for memory that will all be
// used: it is made resident at once.
//
// Why not 2 MiB pages (MADV_HUGEPAGE): on the benchmark VM, whose free memory is handed back to
// the host (page reporting), a command run after a few seconds' pause paid for each large page
// in system time: `camwb-cli post` of 1M moves took 0.90 s instead of 0.56 s (docs/benchmarks.md).
#pragma once

#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace camwb::base {

// Makes the pages of [data, data + bytes) resident and writable. A hint: false where the system
// cannot (an older kernel), and nothing else changes; the memory is used as before.
bool prefault(void* data, std::size_t bytes);

// The same for the first `count` elements of a vector's capacity (reserve() them first).
template <class T> bool prefault(std::vector<T>& v, std::size_t count)
{
    return count <= v.capacity() && prefault(v.data(), count * sizeof(T));
}

// prefault() on a thread of its own, a megabyte at a time from the start, while the caller fills
// the memory from the start too: a page the caller reaches first it faults itself, the others are
// there when it comes. For memory filled with work between the writes (the simulator's moves,
// built from the program: 20 MB for the 20k-block benchmark, whose simulation went from 65.3-68.5
// to 59.3-63.5 ms, perf stat, 40 runs, three rounds). Below kMinBytes the thread costs more than
// it saves, and the range is faulted in at once, as where no thread can be had. The destructor
// stops and waits for it. Populating writes no byte: were the memory freed meanwhile (a vector
// that grew past its reservation), the thread would only fault in, or fail on, what is mapped there.
class PrefaultBeside {
public:
    static constexpr std::size_t kMinBytes = std::size_t(4) << 20;

    PrefaultBeside(void* data, std::size_t bytes);
    ~PrefaultBeside();
    PrefaultBeside(const PrefaultBeside&) = delete;
    PrefaultBeside& operator=(const PrefaultBeside&) = delete;

private:
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

}  // namespace camwb::base
