#include "base/Prefault.h"

#include <algorithm>
#include <cstdint>
#include <system_error>

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace camwb::base {

bool prefault(void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    if (data == nullptr || bytes == 0)
        return false;
    // madvise() takes whole pages: the partial ones at the ends belong to the same mapping.
    const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const auto first = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t begin = first & ~(page - 1);
    const std::uintptr_t end = (first + bytes + page - 1) & ~(page - 1);
    return ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE) == 0;
#else
    (void)data, (void)bytes;
    return false;
#endif
}

PrefaultBeside::PrefaultBeside(void* data, std::size_t bytes)
{
    if (bytes < kMinBytes) {
        prefault(data, bytes);
        return;
    }
    auto populate = [this, begin = static_cast<char*>(data), bytes] {
        constexpr std::size_t kChunk = std::size_t(1) << 20;
        for (std::size_t at = 0; at < bytes && !m_stop.load(std::memory_order_relaxed); at += kChunk)
            if (!prefault(begin + at, std::min(kChunk, bytes - at)))
                return;  // this kernel cannot: the writer faults the pages as before
    };
    try {
        m_thread = std::thread(populate);
    } catch (const std::system_error&) {
        prefault(data, bytes);
    }
}

PrefaultBeside::~PrefaultBeside()
{
    m_stop.store(true, std::memory_order_relaxed);
    if (m_thread.joinable())
        m_thread.join();
}

}  // namespace camwb::base
