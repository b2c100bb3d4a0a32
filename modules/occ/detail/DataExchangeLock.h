// Private: OCCT 7.6's STEP and IGES readers and writers share process-wide state without a lock
// (LibCtl_Library's cache of the last protocol, which every reader and writer rewrites; the IGES
// parser's C globals; OCCT issue #177, made safe only in later OCCT versions). Two models loaded
// at once crashed in STEPControl_Reader's constructor about once in 200 tries. One data exchange
// at a time in this process: meshing and every other use of a loaded shape still run in parallel.
#pragma once

#include <mutex>

namespace camwb::occ::detail {

inline std::mutex& dataExchangeMutex()
{
    static std::mutex mutex;
    return mutex;
}

}  // namespace camwb::occ::detail
