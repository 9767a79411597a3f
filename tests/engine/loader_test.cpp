// SPDX-License-Identifier: Apache-2.0
// Loader: every fixture library is either loaded or rejected with a reason
// that names the problem, never a crash; describe reports both. The raw C
// fixtures have no manifest, so an engine opens them only when a configured id
// is in no manifest; pn_plugins_describe with PN_LIST_OPEN_LIBRARIES opens them all.
#include <dlfcn.h>

#include <map>

#include <doctest/doctest.h>

#include "plugin_listing.hpp"
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
        const auto d = list_plugins({fixture_dir("good"), fixture_dir(c.fixture)}, PN_LIST_OPEN_LIBRARIES);
        REQUIRE(d.is_object());
        REQUIRE(d["rejected"].size() == 1);
        const auto r = rejected_entry(d, std::string("/libpnp_") + c.fixture + ".so");
        REQUIRE(!r.is_null());
        CHECK(r["status"] == c.status);
        const std::string reason = r["reason"];
        for (const auto& m : c.reason_mentions) CHECK_MESSAGE(contains(reason, m), reason);
        // Only the good library's four plugins are offered.
        CHECK(d["plugins"].size() == 4);

        // An engine whose plugins are all in the good library's manifest never opens the bad one.
        Engine e(kGoodConfig, {fixture_dir("good"), fixture_dir(c.fixture)});
        REQUIRE(e.status() == PN_OK);  // a bad file next to good ones does not stop the engine
        CHECK(e.describe()["rejected"].empty());
    }
}

TEST_CASE("a configured id in no manifest opens the libraries without one, in order, until it is found") {
    // Directory order: the five bad raw fixtures, then old_minor, then new_minor.
    std::vector<std::string> dirs;
    for (const char* f : {"good", "wrong_major", "wrong_major_field", "no_entry", "too_small", "too_small_descriptor",
                          "old_minor", "new_minor"})
        dirs.push_back(fixture_dir(f));
    Engine e(make_config({{"position_filter", "org.pednav.test.old_minor"}}), dirs);
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    const auto d = e.describe();
    CHECK(d["rejected"].size() == 5);
    for (const char* f : {"wrong_major", "wrong_major_field", "no_entry", "too_small", "too_small_descriptor"})
        CHECK_MESSAGE(!rejected_entry(d, std::string("/libpnp_") + f + ".so").is_null(), f);
    CHECK(is_loaded(fixture_dir("old_minor") + "/libpnp_old_minor.so"));
    CHECK_FALSE(is_loaded(fixture_dir("new_minor") + "/libpnp_new_minor.so"));  // after the one wanted
    const auto good = entry_ending(d, "libraries", "/libpnp_good.so");  // listed by its manifest, not wanted
    REQUIRE(!good.is_null());
    CHECK(good["opened"] == false);
    // Seven libraries found without a manifest, each named once in the warnings.
    CHECK(d["load_warnings"].size() == 7);
    CHECK(!entry_ending(d, "load_warnings", "/libpnp_new_minor.so").is_null());
}

TEST_CASE("all fixture directories at once: six rejected, eight plugins loaded") {
    std::vector<std::string> dirs;
    for (const char* f : {"good", "throws", "emits_nan", "duplicate_id", "wrong_major", "wrong_major_field",
                          "no_entry", "too_small", "too_small_descriptor", "old_minor", "new_minor"})
        dirs.push_back(fixture_dir(f));
    const auto d = list_plugins(dirs, PN_LIST_OPEN_LIBRARIES);
    REQUIRE(d.is_object());
    CHECK(d["rejected"].size() == 6);
    CHECK(d["plugins"].size() == 8);
    for (const auto& p : d["plugins"]) {
        CHECK(p.contains("id"));
        CHECK(p.contains("kind"));
        CHECK(p.contains("version"));
        CHECK(p.contains("library"));
    }

    // An engine on the good library opens it alone: the duplicate id is known from
    // duplicate_id's manifest, the raw fixtures are only found.
    Engine e(kGoodConfig, dirs);
    REQUIRE(e.status() == PN_OK);
    const auto ed = e.describe();
    REQUIRE(ed["rejected"].size() == 1);
    CHECK(contains(ed["rejected"][0]["path"].get<std::string>(), "libpnp_duplicate_id.so"));
    CHECK(ed["plugins"].size() == 6);  // good's four, throws and emits_nan: listed, not opened
    size_t opened = 0;
    for (const auto& l : ed["libraries"]) opened += l["opened"].get<bool>() ? 1 : 0;
    CHECK(opened == 1);
    CHECK(ed["load_warnings"].size() == 7);
}

TEST_CASE("describe lists the good plugins with kind, version, mounts, library file and manifest") {
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
    CHECK(d["plugins"][0]["mounts"] == nlohmann::json({"foot", "chest", "waist"}));
    CHECK(d["rejected"].empty());
    CHECK(d["load_warnings"].empty());
    REQUIRE(d["libraries"].size() == 1);
    CHECK(d["libraries"][0]["opened"] == true);
    CHECK(d["libraries"][0]["manifest"] == fixture_dir("good") + "/libpnp_good.json");
}

TEST_CASE("a missing plugin directory is reported, not fatal") {
    Engine e(kGoodConfig, {fixture_dir("good"), fixture_dir("does_not_exist")});
    REQUIRE(e.status() == PN_OK);
    const auto r = rejected_entry(e.describe(), "/does_not_exist");
    REQUIRE(!r.is_null());
    CHECK(r["status"] == "PN_E_NOT_FOUND");
}

TEST_CASE("rejected files and libraries without a manifest are logged through the app's log callback") {
    std::vector<std::string> lines;
    auto log = [](void* user, int32_t, const char* source, const char* msg) {
        static_cast<std::vector<std::string>*>(user)->push_back(std::string(source) + ": " + msg);
    };
    // old_minor is in no manifest: no_entry, before it, is opened and refused.
    Engine e(make_config({{"position_filter", "org.pednav.test.old_minor"}}),
             {fixture_dir("no_entry"), fixture_dir("old_minor")}, 0, {}, log, &lines);
    REQUIRE(e.status() == PN_OK);
    size_t rejected = 0, no_manifest = 0;
    for (const auto& l : lines) {
        rejected += contains(l, "rejected plugin file") && contains(l, "libpnp_no_entry.so") ? 1 : 0;
        no_manifest += contains(l, "no manifest libpnp_") ? 1 : 0;
    }
    CHECK(rejected == 1);
    CHECK(no_manifest == 2);
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
