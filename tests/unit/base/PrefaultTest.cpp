// base/Prefault.h: the pages of a range are resident after prefault(), and a range that is not
// memory is refused, not faulted.
#include "base/Prefault.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <sys/mman.h>
#include <unistd.h>

using namespace camwb::base;

namespace {

// How many of the pages of a fresh anonymous mapping are resident (mincore).
std::size_t residentPages(void* mapping, std::size_t bytes)
{
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    std::vector<unsigned char> resident((bytes + page - 1) / page);
    if (::mincore(mapping, bytes, resident.data()) != 0)
        return 0;
    std::size_t count = 0;
    for (const unsigned char r : resident)
        count += r & 1;
    return count;
}

struct Mapping {
    explicit Mapping(std::size_t bytes) :
        bytes(bytes),
        data(::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0))
    {
    }
    ~Mapping()
    {
        if (data != MAP_FAILED)
            ::munmap(data, bytes);
    }
    std::size_t bytes;
    void* data;
};

// The kernel knows MADV_POPULATE_WRITE (Linux 5.14): asked directly, not through prefault(), so
// that a prefault() that fails for a reason of its own fails the tests instead of skipping them.
bool kernelPopulates()
{
#ifdef MADV_POPULATE_WRITE
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    Mapping m(page);
    return m.data != MAP_FAILED && ::madvise(m.data, page, MADV_POPULATE_WRITE) == 0;
#else
    return false;
#endif
}

}  // namespace

TEST(Prefault, MakesTheRangeResident)
{
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    Mapping m(64 * page);
    ASSERT_NE(m.data, MAP_FAILED);
    ASSERT_EQ(residentPages(m.data, m.bytes), 0u);  // untouched
    // Pages 10 to 19, from the middle of page 10 to the middle of page 19: whole pages taken.
    auto* bytes = static_cast<unsigned char*>(m.data);
    if (!kernelPopulates())
        GTEST_SKIP() << "this kernel cannot populate memory ahead (MADV_POPULATE_WRITE, Linux 5.14)";
    ASSERT_TRUE(prefault(bytes + 10 * page + page / 2, 9 * page));
    EXPECT_EQ(residentPages(m.data, m.bytes), 10u);
    EXPECT_EQ(residentPages(bytes + 10 * page, 10 * page), 10u);
    bytes[15 * page] = 7;  // and writable, with its contents zero
    EXPECT_EQ(bytes[15 * page], 7);
    EXPECT_EQ(bytes[16 * page], 0);
}

TEST(Prefault, AVectorsFirstElements)
{
    std::vector<double> v;
    v.reserve(100000);
    EXPECT_FALSE(prefault(v, 100001));  // more than it holds: refused, nothing touched
    if (!kernelPopulates())
        GTEST_SKIP() << "this kernel cannot populate memory ahead (MADV_POPULATE_WRITE, Linux 5.14)";
    ASSERT_TRUE(prefault(v, 100000));
    v.assign(100000, 2.5);
    EXPECT_EQ(v[99999], 2.5);
}

TEST(Prefault, RefusesWhatIsNotMemory)
{
    EXPECT_FALSE(prefault(nullptr, 4096));
    int x = 0;
    EXPECT_FALSE(prefault(&x, 0));
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    Mapping m(4 * page);
    ASSERT_NE(m.data, MAP_FAILED);
    ::munmap(static_cast<unsigned char*>(m.data) + 2 * page, 2 * page);  // a hole after two pages
    m.bytes = 2 * page;
    EXPECT_FALSE(prefault(m.data, 4 * page));  // runs into the hole
}

TEST(Prefault, BesideTheWriterChangesNoByteItWrites)
{
    // A megabyte at a time on the thread while the writer fills the same pages: every byte the
    // writer wrote is there afterwards (populating writes nothing).
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const std::size_t bytes = PrefaultBeside::kMinBytes + 40 * page + 123;
    Mapping m((bytes + page - 1) / page * page);
    ASSERT_NE(m.data, MAP_FAILED);
    auto* data = static_cast<unsigned char*>(m.data);
    {
        const PrefaultBeside ahead(data, bytes);
        for (std::size_t at = 0; at < bytes; at += page / 3 + 1)
            data[at] = static_cast<unsigned char>(at % 251 + 1);
    }
    for (std::size_t at = 0; at < bytes; at += page / 3 + 1)
        ASSERT_EQ(data[at], at % 251 + 1) << at;
    for (std::size_t at = 1; at < bytes; at += page / 3 + 1)
        ASSERT_EQ(data[at], 0) << at;
}

TEST(Prefault, BesideASmallRangeFaultsItInAtOnce)
{
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    Mapping m(16 * page);
    ASSERT_NE(m.data, MAP_FAILED);
    const PrefaultBeside ahead(m.data, m.bytes);  // below kMinBytes: no thread
    if (!kernelPopulates())
        GTEST_SKIP() << "this kernel cannot populate memory ahead (MADV_POPULATE_WRITE, Linux 5.14)";
    EXPECT_EQ(residentPages(m.data, m.bytes), 16u);
    const PrefaultBeside nothing(nullptr, 0);  // nothing to do, and nothing done
}
