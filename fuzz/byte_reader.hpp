// SPDX-License-Identifier: Apache-2.0
// Reads the fuzz input as a stream of small values; past the end every value
// is zero and done() is true, so a decoder never reads out of bounds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace pednav::fuzz {

class ByteReader {
public:
    ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

    bool done() const { return at_ >= size_; }
    uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
    uint16_t u16() { return static_cast<uint16_t>(u8() | (u8() << 8)); }
    int16_t i16() { return static_cast<int16_t>(u16()); }
    uint32_t u32() { return static_cast<uint32_t>(u16()) | (static_cast<uint32_t>(u16()) << 16); }
    uint64_t u64() { return static_cast<uint64_t>(u32()) | (static_cast<uint64_t>(u32()) << 32); }
    // Any bit pattern: NaN, infinities, denormals, huge values.
    double raw_double() {
        const uint64_t bits = u64();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    // The next `n` bytes (fewer at the end).
    std::string_view bytes(size_t n) {
        const size_t take = at_ < size_ ? (n < size_ - at_ ? n : size_ - at_) : 0;
        const std::string_view out(reinterpret_cast<const char*>(data_ + at_), take);
        at_ += take;
        return out;
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t at_ = 0;
};

}  // namespace pednav::fuzz
