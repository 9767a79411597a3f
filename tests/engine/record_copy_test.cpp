// SPDX-License-Identifier: Apache-2.0
// White-box tests of how the engine copies the records it is handed
// (record_copy.hpp): exactly struct_size bytes, whatever the size, and the
// queues built on it keep what they are given.
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "output_queue.hpp"
#include "record_copy.hpp"
#include "record_queue.hpp"

using namespace pednav::engine;

namespace {

// A record buffer of `size` bytes: a header, then bytes counting up.
std::vector<unsigned char> pattern(uint32_t size, pn_record_type_t type) {
    std::vector<unsigned char> b(PN_RECORD_MAX_SIZE);
    for (size_t i = 0; i < b.size(); ++i) b[i] = static_cast<unsigned char>(i * 7 + 3);
    pn_record_header_t h{};
    h.struct_size = size;
    h.type = type;
    h.t_ns = 1234567;
    std::memcpy(b.data(), &h, sizeof h);
    return b;
}

}  // namespace

TEST_CASE("copy_record copies exactly struct_size bytes, also sizes that are not whole words") {
    for (uint32_t size : {24u, 25u, 31u, 32u, 100u, 167u, 504u, 511u, 512u}) {
        CAPTURE(size);
        alignas(8) unsigned char src[PN_RECORD_MAX_SIZE];
        const auto p = pattern(size, PN_REC_POSITION);
        std::memcpy(src, p.data(), sizeof src);
        alignas(8) unsigned char dst[PN_RECORD_MAX_SIZE + 8];
        std::memset(dst, 0xEE, sizeof dst);
        copy_record(dst, reinterpret_cast<const pn_record_header_t*>(src));
        CHECK(std::memcmp(dst, src, size) == 0);
        size_t untouched = 0;
        for (size_t i = size; i < sizeof dst; ++i) untouched += dst[i] == 0xEE;
        CHECK(untouched == sizeof dst - size);
    }
}

TEST_CASE("record queue keeps records of any size through a grow") {
    RecordQueue q(4);
    std::vector<std::vector<unsigned char>> sent;
    for (uint32_t k = 0; k < 10; ++k) {
        const uint32_t size = 24 + 13 * k;  // 24, 37, 50, ...: most not whole words
        sent.push_back(pattern(size, PN_REC_IMU));
        q.push(reinterpret_cast<const pn_record_header_t*>(sent.back().data()));
    }
    CHECK(q.capacity() == 16);
    for (uint32_t k = 0; k < 10; ++k) {
        const pn_record_header_t* r = q.at(q.begin() + k);
        REQUIRE(r->struct_size == 24 + 13 * k);
        CHECK(std::memcmp(r, sent[k].data(), r->struct_size) == 0);
    }
}

TEST_CASE("output queue stamps the source after the copy, in the queue and the latest") {
    OutputQueue q(4);
    auto p = pattern(sizeof(pn_position_t), PN_REC_POSITION);
    reinterpret_cast<pn_record_header_t*>(p.data())->source_id = 99;
    q.push(reinterpret_cast<const pn_record_header_t*>(p.data()), 7);
    pn_output_t out{}, latest{};
    REQUIRE(q.pop(&out));
    REQUIRE(q.latest(PN_REC_POSITION, &latest));
    for (const pn_output_t* o : {&out, &latest}) {
        CHECK(o->header.source_id == 7);
        CHECK(o->header.t_ns == 1234567);
        CHECK(std::memcmp(o->bytes + sizeof(pn_record_header_t), p.data() + sizeof(pn_record_header_t),
                          sizeof(pn_position_t) - sizeof(pn_record_header_t)) == 0);
    }
}

TEST_CASE("output queue: the newest record of each type survives the reuse of its slot and a full queue") {
    OutputQueue q(3);
    auto record = [](pn_record_type_t type, int64_t t_ns) {
        auto p = pattern(type == PN_REC_STRIDE ? sizeof(pn_stride_t) : sizeof(pn_position_t), type);
        reinterpret_cast<pn_record_header_t*>(p.data())->t_ns = t_ns;
        return p;
    };
    auto push = [&](pn_record_type_t type, int64_t t_ns) {
        const auto p = record(type, t_ns);
        return q.push(reinterpret_cast<const pn_record_header_t*>(p.data()), 2);
    };
    pn_output_t out{}, latest{};
    CHECK_FALSE(q.latest(PN_REC_STRIDE, &latest));
    REQUIRE(push(PN_REC_STRIDE, 10));
    // Positions go round the ring: the stride's slot is reused by the third one.
    for (int64_t t = 11; t <= 16; ++t) {
        REQUIRE(push(PN_REC_POSITION, t));
        while (q.pop(&out)) {
        }
    }
    REQUIRE(q.latest(PN_REC_STRIDE, &latest));
    CHECK(latest.header.t_ns == 10);
    CHECK(latest.header.struct_size == sizeof(pn_stride_t));
    CHECK(latest.header.source_id == 2);
    const auto expected = record(PN_REC_STRIDE, 10);
    CHECK(std::memcmp(latest.bytes + sizeof(pn_record_header_t), expected.data() + sizeof(pn_record_header_t),
                      sizeof(pn_stride_t) - sizeof(pn_record_header_t)) == 0);
    REQUIRE(q.latest(PN_REC_POSITION, &latest));
    CHECK(latest.header.t_ns == 16);
    // Full (nobody polls): dropped records still become the newest.
    REQUIRE(push(PN_REC_POSITION, 17));
    REQUIRE(push(PN_REC_POSITION, 18));
    REQUIRE(push(PN_REC_POSITION, 19));
    CHECK_FALSE(push(PN_REC_POSITION, 20));
    CHECK_FALSE(push(PN_REC_STRIDE, 21));
    CHECK(q.dropped() == 2);
    REQUIRE(q.latest(PN_REC_POSITION, &latest));
    CHECK(latest.header.t_ns == 20);
    REQUIRE(q.latest(PN_REC_STRIDE, &latest));
    CHECK(latest.header.t_ns == 21);
    // The queue itself kept the three before the drops, in order.
    for (int64_t t = 17; t <= 19; ++t) {
        REQUIRE(q.pop(&out));
        CHECK(out.header.t_ns == t);
    }
    CHECK_FALSE(q.pop(&out));
    q.clear();
    CHECK_FALSE(q.latest(PN_REC_POSITION, &latest));
}
