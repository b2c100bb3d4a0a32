#include "base/Prefault.h"

#include <cstdint>

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

}  // namespace camwb::base
