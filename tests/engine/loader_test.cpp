// Loader: every fixture library is either loaded or rejected with a reason
// that names the problem, never a crash; describe reports both.
#include <dlfcn.h>

#include <map>

#include <doctest/doctest.h>

#include "test_support.hpp"

using namespace pednav::test;

namespace {

const std::string kGoodConfig = make_config({{"step_detector", "org.pednav.test.counting_steps"}});

struct Rejection {
    const char* fixture;
    const char* status;
    std::vector<std::string> reason_mentions;
};

}  // namespace

TEST_CASE("each bad fixture is rejected with its file, status and a reason naming the problem") {
    const Rejection cases[] = {
        {"wrong_major", "PN_E_ABI_MISMATCH", {"pnp_entry_v2", "pnp_entry_v1"}},
        {"wrong_major_field", "PN_E_ABI_MISMATCH", {"major 2"}},
        {"no_entry", "PN_E_NOT_FOUND", {"pnp_entry_v1"}},
        {"too_small", "PN_E_ABI_MISMATCH", {"struct_size 40", "56"}},
        {"too_small_descriptor", "PN_E_ABI_MISMATCH", {"struct_size 88", "104"}},
    };
    for (const auto& c : cases) {
        CAPTURE(c.fixture);
        Engine e(kGoodConfig, {fixture_dir("good"), fixture_dir(c.fixture)});
        REQUIRE(e.status() == PN_OK);  // a bad file next to good ones does not stop the engine
        const auto d = e.describe();
        REQUIRE(d["rejected"].size() == 1);
        const auto r = rejected_entry(d, std::string("/libpnp_") + c.fixture + ".so");
        REQUIRE(!r.is_null());
        CHECK(r["status"] == c.status);
        const std::string reason = r["reason"];
        for (const auto& m : c.reason_mentions) CHECK_MESSAGE(contains(reason, m), reason);
        // Only the good library's four plugins are offered.
        CHECK(d["plugins"].size() == 4);
    }
}

TEST_CASE("a duplicate plugin id is rejected naming the id and the library that already provides it") {
    Engine e(kGoodConfig, {fixture_dir("good"), fixture_dir("duplicate_id")});
    REQUIRE(e.status() == PN_OK);
    const auto d = e.describe();
    const auto r = rejected_entry(d, "/libpnp_duplicate_id.so");
    REQUIRE(!r.is_null());
    const std::string reason = r["reason"];
    CHECK(contains(reason, "duplicate"));
    CHECK(contains(reason, "org.pednav.test.counting_steps"));
    CHECK(contains(reason, "libpnp_good.so"));
    // The id still resolves to the first library, the good one.
    for (const auto& p : d["plugins"])
        if (p["id"] == "org.pednav.test.counting_steps") CHECK(p["version"] == "1.0.0");
}

TEST_CASE("all fixture directories at once: six rejected, eight plugins loaded") {
    std::vector<std::string> dirs;
    for (const char* f : {"good", "throws", "emits_nan", "duplicate_id", "wrong_major", "wrong_major_field",
                          "no_entry", "too_small", "too_small_descriptor", "old_minor", "new_minor"})
        dirs.push_back(fixture_dir(f));
    Engine e(kGoodConfig, dirs);
    REQUIRE(e.status() == PN_OK);
    const auto d = e.describe();
    CHECK(d["rejected"].size() == 6);
    CHECK(d["plugins"].size() == 8);
    for (const auto& p : d["plugins"]) {
        CHECK(p.contains("id"));
        CHECK(p.contains("kind"));
        CHECK(p.contains("version"));
        CHECK(p.contains("library"));
    }
}

TEST_CASE("describe lists the good plugins with kind, version and library file") {
    Engine e(kGoodConfig, {fixture_dir("good")});
    REQUIRE(e.status() == PN_OK);
    const auto d = e.describe();
    std::map<std::string, std::string> kinds;
    for (const auto& p : d["plugins"]) {
        kinds[p["id"]] = p["kind"];
        CHECK(p["version"] == "1.0.0");
        CHECK(contains(p["library"].get<std::string>(), "libpnp_good.so"));
    }
    CHECK(kinds["org.pednav.test.counting_steps"] == "step_detector");
    CHECK(kinds["org.pednav.test.fixed_heading"] == "attitude_estimator");
    CHECK(kinds["org.pednav.test.step_counter"] == "position_filter");
    CHECK(kinds["org.pednav.test.floor_from_baro"] == "map_matcher");
    CHECK(d["rejected"].empty());
}

TEST_CASE("a missing plugin directory is reported, not fatal") {
    Engine e(kGoodConfig, {fixture_dir("good"), fixture_dir("does_not_exist")});
    REQUIRE(e.status() == PN_OK);
    const auto r = rejected_entry(e.describe(), "/does_not_exist");
    REQUIRE(!r.is_null());
    CHECK(r["status"] == "PN_E_NOT_FOUND");
}

TEST_CASE("rejected files are logged through the app's log callback") {
    std::vector<std::string> lines;
    auto log = [](void* user, int32_t, const char* source, const char* msg) {
        static_cast<std::vector<std::string>*>(user)->push_back(std::string(source) + ": " + msg);
    };
    Engine e(kGoodConfig, {fixture_dir("good"), fixture_dir("no_entry")}, 0, {}, log, &lines);
    REQUIRE(e.status() == PN_OK);
    bool found = false;
    for (const auto& l : lines) found = found || contains(l, "libpnp_no_entry.so");
    CHECK(found);
}

TEST_CASE(
    "old minor: a vtable trimmed to PNP_NODE_OPS_MIN_SIZE loads and runs; absent slots are never called") {
    Engine e(make_config({{"position_filter", "org.pednav.test.old_minor"}}), {fixture_dir("old_minor")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    CHECK(pn_engine_latency_ns(e.get()) == 0);
    // No set_start slot: the engine says so instead of calling past the vtable.
    const double start[3] = {1, 2, 3};
    CHECK(pn_engine_set_start(e.get(), start, 0.0, nullptr) == PN_E_UNSUPPORTED);
    REQUIRE(push(e, walk(0, 100)) == PN_OK);
    REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);  // no flush slot either
    const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
    REQUIRE(pos.size() == 10);
    for (size_t i = 0; i < pos.size(); ++i) {
        CHECK(pos[i].position.pos_enu_m[0] == static_cast<double>(i + 1));
        CHECK(pos[i].header.t_ns == sample_t_ns(10 * i + 9));
    }
    CHECK(pn_engine_reset(e.get(), nullptr) == PN_OK);
}

TEST_CASE("new minor: larger structs and records with unknown tails load and pass through") {
    Engine e(make_config({{"position_filter", "org.pednav.test.new_minor"}}), {fixture_dir("new_minor")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    REQUIRE(push(e, walk(0, 100)) == PN_OK);
    REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
    const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
    REQUIRE(pos.size() == 10);
    for (size_t i = 0; i < pos.size(); ++i) {
        CHECK(pos[i].position.pos_enu_m[0] == static_cast<double>(i + 1));
        CHECK(pos[i].header.struct_size >= sizeof(pn_position_t));
    }
}

TEST_CASE("a library passed in static_libraries works like a loaded one") {
    // Stands in for an app that links a plugin library statically (iOS).
    void* h = dlopen((fixture_dir("good") + "/libpnp_good.so").c_str(), RTLD_NOW | RTLD_LOCAL);
    REQUIRE(h != nullptr);
    auto entry = reinterpret_cast<pnp_entry_fn>(dlsym(h, PNP_ENTRY_SYMBOL));
    REQUIRE((entry != nullptr));
    {
        Engine e(kGoodConfig, {}, 0, {entry()});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        REQUIRE(push(e, walk(0, 50)) == PN_OK);
        REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
        CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 5);
    }
    dlclose(h);
}
