// The text of the motion trace as it is built (nc/MotionTrace.cpp only): a growable buffer that
// appends without std::string's checks, and a cache of recently formatted numbers. Internal to
// the trace writer; nothing else includes it.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string_view>

// The pieces of a trace line are a few bytes each: inlined into the entry that writes them, keys
// become stores of known bytes instead of calls (GCC would not inline them on its own at -O2).
#define CAMWB_TRACE_INLINE [[gnu::always_inline]] inline

namespace camwb::nc::detail {

// The text being built: room is made once per piece, so that appending is a plain copy, without
// std::string's checks and calls on every word (a trace line has about twenty pieces).
class TextBuffer {
public:
    // At least `bytes` writable bytes at the end.
    CAMWB_TRACE_INLINE char* room(std::size_t bytes)
    {
        if (m_capacity - m_size < bytes)
            grow(bytes);
        return m_data.get() + m_size;
    }
    void commit(const char* end) { m_size = static_cast<std::size_t>(end - m_data.get()); }
    CAMWB_TRACE_INLINE TextBuffer& operator+=(std::string_view text)
    {
        std::memcpy(room(text.size()), text.data(), text.size());
        m_size += text.size();
        return *this;
    }
    CAMWB_TRACE_INLINE TextBuffer& operator+=(char c)
    {
        *room(1) = c;
        ++m_size;
        return *this;
    }
    std::string_view view() const { return {m_data.get(), m_size}; }
    std::size_t size() const { return m_size; }
    void clear() { m_size = 0; }
    void reserve(std::size_t bytes) { room(bytes); }

private:
    void grow(std::size_t bytes)
    {
        const std::size_t capacity = std::max({m_capacity * 2, m_size + bytes, std::size_t(4096)});
        auto data = std::make_unique<char[]>(capacity);
        if (m_size > 0)
            std::memcpy(data.get(), m_data.get(), m_size);
        m_data = std::move(data);
        m_capacity = capacity;
    }

    std::unique_ptr<char[]> m_data;
    std::size_t m_size = 0;
    std::size_t m_capacity = 0;
};

// The text of recently written numbers: the state fields (feed, spindle), an arc's normal and an
// axis that did not move repeat from entry to entry, and copying their text is far cheaper than
// formatting it again. Keyed by the exact bits, so the text is the one formatting would give.
class NumberCache {
public:
    static constexpr std::size_t kLongest = 24;

    // The cached text of `value` (kLongest bytes copied to `out`), its length or 0 when not cached.
    CAMWB_TRACE_INLINE std::size_t find(double value, char* out) const
    {
        const Slot& slot = m_slots[index(value)];
        if (slot.length == 0 || slot.bits != std::bit_cast<std::uint64_t>(value))
            return 0;
        std::memcpy(out, slot.text, kLongest);
        return slot.length;
    }
    CAMWB_TRACE_INLINE void store(double value, const char* text, std::size_t length)
    {
        if (length > kLongest)
            return;
        Slot& slot = m_slots[index(value)];
        slot.bits = std::bit_cast<std::uint64_t>(value);
        slot.length = length;
        std::memcpy(slot.text, text, length);
    }

private:
    struct Slot {
        std::uint64_t bits = 0;
        std::size_t length = 0;
        char text[kLongest] = {};
    };
    static std::size_t index(double value)
    {
        return static_cast<std::size_t>((std::bit_cast<std::uint64_t>(value) * 0x9E3779B97F4A7C15ull) >> 60);
    }
    Slot m_slots[16];
};

}  // namespace camwb::nc::detail
