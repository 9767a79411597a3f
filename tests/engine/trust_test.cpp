// SPDX-License-Identifier: Apache-2.0
// The trust model (README, "Trust model"): libraries load only from the
// directories the app gives; a world-writable directory or library, and a
// symbolic link leading out of the directory, are refused with the reason;
// a library whose plugin_count is larger than its plugins array is refused
// naming plugin_count, its pointers never followed.
#include <sys/stat.h>

#include <filesystem>

#include <doctest/doctest.h>

#include "plugin_listing.hpp"
#include "test_support.hpp"

using namespace pednav::test;
namespace fs = std::filesystem;

namespace {

const std::string kGoodConfig = make_config({{"step_detector", "org.pednav.test.counting_steps"}});

// A fresh directory <work>/trust/<name>, mode 0755.
fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::path(PEDNAV_TEST_WORK_DIR) / "trust" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (fs::path p = dir; p != fs::path(PEDNAV_TEST_WORK_DIR).parent_path(); p = p.parent_path())
        chmod(p.c_str(), 0755);
    return dir;
}

// The good fixture library and its manifest copied into `dir` (modes 0755, 0644).
void copy_good(const fs::path& dir) {
    const fs::path from = fixture_dir("good");
    fs::copy_file(from / "libpnp_good.so", dir / "libpnp_good.so");
    fs::copy_file(from / "libpnp_good.json", dir / "libpnp_good.json");
    chmod((dir / "libpnp_good.so").c_str(), 0755);
    chmod((dir / "libpnp_good.json").c_str(), 0644);
}

}  // namespace

TEST_CASE("a copy of a good library in a directory of mode 0755 loads (the baseline of the cases below)") {
    const fs::path dir = fresh_dir("baseline");
    copy_good(dir);
    Engine e(kGoodConfig, {dir.string()});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    CHECK(e.describe()["rejected"].empty());
}

TEST_CASE("a world-writable plugin directory is not scanned, and the load report says why") {
    const fs::path dir = fresh_dir("world_writable_dir");
    copy_good(dir);
    chmod(dir.c_str(), 0777);
    const auto d = list_plugins({dir.string()}, PN_LIST_OPEN_LIBRARIES);
    REQUIRE(d.is_object());
    CHECK(d["plugins"].empty());
    REQUIRE(d["rejected"].size() == 1);
    CHECK(d["rejected"][0]["path"] == fs::canonical(dir).string());
    CHECK(d["rejected"][0]["status"] == "PN_E_IO");
    CHECK_MESSAGE(contains(d["rejected"][0]["reason"], "the plugin directory is world-writable (mode 0777)"),
                  d["rejected"][0]["reason"]);
    Engine e(kGoodConfig, {dir.string()});
    CHECK(e.status() == PN_E_NOT_FOUND);
    CHECK_FALSE(is_loaded((dir / "libpnp_good.so").string()));
    chmod(dir.c_str(), 0755);
}

TEST_CASE("a world-writable library is not opened, and the load report says why") {
    const fs::path dir = fresh_dir("world_writable_library");
    copy_good(dir);
    chmod((dir / "libpnp_good.so").c_str(), 0757);
    const auto d = list_plugins({dir.string()}, PN_LIST_OPEN_LIBRARIES);
    REQUIRE(d.is_object());
    CHECK(d["plugins"].empty());
    const auto r = rejected_entry(d, "/world_writable_library/libpnp_good.so");
    REQUIRE(!r.is_null());
    CHECK_MESSAGE(contains(r["reason"], "the library is world-writable (mode 0757): anyone could change it; not opened"),
                  r["reason"]);
    Engine e(kGoodConfig, {dir.string()});
    CHECK(e.status() == PN_E_NOT_FOUND);
    CHECK_FALSE(is_loaded((dir / "libpnp_good.so").string()));
}

TEST_CASE("a symbolic link to a library outside the plugin directory is refused; one inside it is followed") {
    SUBCASE("outside") {
        const fs::path dir = fresh_dir("link_outside");
        fs::create_symlink(fs::path(fixture_dir("good")) / "libpnp_good.so", dir / "libpnp_good.so");
        fs::copy_file(fs::path(fixture_dir("good")) / "libpnp_good.json", dir / "libpnp_good.json");
        const auto d = list_plugins({dir.string()}, PN_LIST_OPEN_LIBRARIES);
        REQUIRE(d.is_object());
        CHECK(d["plugins"].empty());
        REQUIRE(d["rejected"].size() == 1);
        const std::string reason = d["rejected"][0]["reason"];
        CHECK_MESSAGE(contains(reason, "libpnp_good.so is a symbolic link to " +
                                           fs::canonical(fs::path(fixture_dir("good")) / "libpnp_good.so").string() +
                                           ", outside the plugin directory " + fs::canonical(dir).string()),
                      reason);
        Engine e(kGoodConfig, {dir.string()});
        CHECK(e.status() == PN_E_NOT_FOUND);
    }
    SUBCASE("inside: a versioned file in a subdirectory") {
        const fs::path dir = fresh_dir("link_inside");
        fs::create_directories(dir / "versions");
        chmod((dir / "versions").c_str(), 0755);
        fs::copy_file(fs::path(fixture_dir("good")) / "libpnp_good.so", dir / "versions" / "libpnp_good.so.1");
        chmod((dir / "versions" / "libpnp_good.so.1").c_str(), 0755);
        fs::create_symlink("versions/libpnp_good.so.1", dir / "libpnp_good.so");
        fs::copy_file(fs::path(fixture_dir("good")) / "libpnp_good.json", dir / "libpnp_good.json");
        Engine e(kGoodConfig, {dir.string()});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        CHECK(e.describe()["rejected"].empty());
    }
}

TEST_CASE("a plugin_count larger than the plugins array is refused naming plugin_count, without a crash") {
    const auto d = list_plugins({fixture_dir("rt_lying_count")}, PN_LIST_OPEN_LIBRARIES);
    REQUIRE(d.is_object());
    CHECK(d["plugins"].empty());
    const auto r = rejected_entry(d, "/libpnp_rt_lying_count.so");
    REQUIRE(!r.is_null());
    CHECK(r["status"] == "PN_E_INVALID_ARGUMENT");
    const std::string reason = r["reason"];
    CHECK_MESSAGE(contains(reason, "plugin_count 1000"), reason);
    // An engine asking for its plugin opens it (no manifest), refuses it and says the id is not available.
    Engine e(make_config({{"position_filter", "org.pednav.test.rt_lying_count"}}), {fixture_dir("rt_lying_count")});
    CHECK(e.status() == PN_E_NOT_FOUND);
    CHECK_MESSAGE(contains(e.error().message, "org.pednav.test.rt_lying_count is not available"), e.error().message);
}
