// SPDX-License-Identifier: Apache-2.0
// Copying a record the engine was just handed: exactly struct_size bytes, in
// 16-byte pieces, with no loop: a jump into an unrolled run of pieces (one
// per full 16 bytes), then the last 16 bytes, which overlap the piece before
// when the size is not a multiple of 16. A 160-byte attitude is ten loads and
// ten stores and one jump.
#pragma once

#include <cstdint>
#include <cstring>

#include <pednav/pn_types.h>

namespace pednav::engine {

namespace detail {
inline void copy16(unsigned char* out, const unsigned char* src, uint32_t at) {
    std::memcpy(out + at, src + at, 16);
}
}  // namespace detail

// Copies r->struct_size bytes of `r` (at most PN_RECORD_MAX_SIZE) to `dst`.
inline void copy_record(void* dst, const pn_record_header_t* r) {
    static_assert(PN_RECORD_MAX_SIZE == 512, "one case per 16 bytes of a record");
    const uint32_t size = r->struct_size;
    const auto* src = reinterpret_cast<const unsigned char*>(r);
    auto* out = static_cast<unsigned char*>(dst);
    if (size < 16 || size > PN_RECORD_MAX_SIZE) {  // never a valid record (the header alone is 24 bytes)
        std::memcpy(out, src, size < PN_RECORD_MAX_SIZE ? size : PN_RECORD_MAX_SIZE);
        return;
    }
    detail::copy16(out, src, size - 16);  // the last piece
    using detail::copy16;
    switch ((size - 1) / 16) {  // the full pieces before it
        case 31: copy16(out, src, 480); [[fallthrough]];
        case 30: copy16(out, src, 464); [[fallthrough]];
        case 29: copy16(out, src, 448); [[fallthrough]];
        case 28: copy16(out, src, 432); [[fallthrough]];
        case 27: copy16(out, src, 416); [[fallthrough]];
        case 26: copy16(out, src, 400); [[fallthrough]];
        case 25: copy16(out, src, 384); [[fallthrough]];
        case 24: copy16(out, src, 368); [[fallthrough]];
        case 23: copy16(out, src, 352); [[fallthrough]];
        case 22: copy16(out, src, 336); [[fallthrough]];
        case 21: copy16(out, src, 320); [[fallthrough]];
        case 20: copy16(out, src, 304); [[fallthrough]];
        case 19: copy16(out, src, 288); [[fallthrough]];
        case 18: copy16(out, src, 272); [[fallthrough]];
        case 17: copy16(out, src, 256); [[fallthrough]];
        case 16: copy16(out, src, 240); [[fallthrough]];
        case 15: copy16(out, src, 224); [[fallthrough]];
        case 14: copy16(out, src, 208); [[fallthrough]];
        case 13: copy16(out, src, 192); [[fallthrough]];
        case 12: copy16(out, src, 176); [[fallthrough]];
        case 11: copy16(out, src, 160); [[fallthrough]];
        case 10: copy16(out, src, 144); [[fallthrough]];
        case 9: copy16(out, src, 128); [[fallthrough]];
        case 8: copy16(out, src, 112); [[fallthrough]];
        case 7: copy16(out, src, 96); [[fallthrough]];
        case 6: copy16(out, src, 80); [[fallthrough]];
        case 5: copy16(out, src, 64); [[fallthrough]];
        case 4: copy16(out, src, 48); [[fallthrough]];
        case 3: copy16(out, src, 32); [[fallthrough]];
        case 2: copy16(out, src, 16); [[fallthrough]];
        case 1: copy16(out, src, 0); [[fallthrough]];
        default: break;
    }
}

}  // namespace pednav::engine
