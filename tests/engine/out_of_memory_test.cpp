// SPDX-License-Identifier: Apache-2.0
// Running out of memory while a plugin emits must not terminate the app: the
// engine's sink runs inside noexcept plugin calls, so it describes a refused
// record without allocating, and the failure comes back as a status. This
// executable replaces the global operator new to fail on demand (which also
// reaches libpednav.so and the plugins), so it is a test binary of its own.
#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "test_support.hpp"

namespace {
std::atomic<bool> g_fail_allocations{false};
std::atomic<long> g_failed{0};

void* allocate(std::size_t n) {
    if (g_fail_allocations.load(std::memory_order_relaxed)) {
        g_failed.fetch_add(1, std::memory_order_relaxed);
        throw std::bad_alloc();
    }
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return allocate(n);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace pednav::test;

TEST_CASE("no memory while the sink refuses a plugin's record: a status, not a termination") {
    Engine e(make_config({{"position_filter", "org.pednav.test.emits_nan", {{"nan_at", 5}}}}), {fixture_dir("emits_nan")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    REQUIRE(push(e, walk(0, 3)) == PN_OK);
    const std::vector<pn_imu_t> samples = walk(3, 5);  // sample 5 is the NaN one
    pn_error_t err = make_error();

    g_fail_allocations = true;
    const pn_status_t st = pn_engine_push_imu(e.get(), samples.data(), samples.size(), sizeof(pn_imu_t), &err);
    g_fail_allocations = false;

    CHECK(g_failed.load() > 0);  // the path did try to allocate
    CHECK(PN_FAILED(st));
    CHECK((st == PN_E_OUT_OF_MEMORY || st == PN_E_NUMERIC));
    // The engine goes on once memory is back, with the outputs made before.
    REQUIRE(push(e, walk(8, 10)) == PN_OK);
    const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
    CHECK(pos.size() >= 4);
    CHECK(pos.front().position.pos_enu_m[0] == 1.0);
}
