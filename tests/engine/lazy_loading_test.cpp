// SPDX-License-Identifier: Apache-2.0
// Lazy loading through manifests: an engine opens only the libraries of the
// plugins its config names; a manifest that disagrees with its library, a
// library without a manifest and a malformed manifest are each reported with
// the file named. The lazy fixtures (lazy/lazy_plugin.c) leave a mark when
// opened, so "not opened" means no code of theirs ran.
#include <filesystem>
#include <fstream>
#include <set>

#include <doctest/doctest.h>

#include "plugin_listing.hpp"
#include "test_support.hpp"

using namespace pednav::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string lazy_path(const std::string& name) {
    return fixture_dir(std::string("lazy_") + name[5]) + "/libpnp_" + name + ".so";
}

std::string lazy_config(const std::string& steps, const std::string& attitude, const std::string& filter) {
    return make_config({{"step_detector", "org.pednav.test." + steps + ".steps"},
                        {"attitude_estimator", "org.pednav.test." + attitude + ".attitude"},
                        {"position_filter", "org.pednav.test." + filter + ".filter"}});
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
void write_text(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// A fresh directory under the build tree holding a copy of lazy_a1 (and, with
// `manifest`, its manifest), for a test to spoil.
std::string lazy_a1_copy(const std::string& test, bool manifest = true) {
    const fs::path dir = fs::path(PEDNAV_TEST_WORK_DIR) / test;
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(lazy_path("lazy_a1"), dir / "libpnp_lazy_a1.so");
    if (manifest) fs::copy_file(fixture_dir("lazy_a") + "/libpnp_lazy_a1.json", dir / "libpnp_lazy_a1.json");
    return dir.string();
}

size_t count_opened(const json& d) {
    size_t n = 0;
    for (const auto& l : d["libraries"]) n += l["opened"].get<bool>() ? 1 : 0;
    return n;
}

}  // namespace

TEST_CASE("a foot engine over two directories of ten libraries opens exactly the three it uses") {
    clear_marks();
    const std::vector<std::string> dirs = {fixture_dir("lazy_a"), fixture_dir("lazy_b")};
    const std::set<std::string> used = {"lazy_a2", "lazy_b1", "lazy_b4"};
    {
        Engine e(lazy_config("lazy_a2", "lazy_b1", "lazy_b4"), dirs);
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        for (const auto& name : lazy_names()) {
            CAPTURE(name);
            CHECK(marked(name) == (used.count(name) == 1));                // its initializer ran
            CHECK(is_loaded(lazy_path(name)) == (used.count(name) == 1));  // and it is still open
        }
        const json d = e.describe();
        CHECK(d["libraries"].size() == 10);
        CHECK(count_opened(d) == 3);
        CHECK(d["plugins"].size() == 30);  // every plugin listed, from the manifests
        CHECK(d["rejected"].empty());
        CHECK(d["load_warnings"].empty());

        // The three opened libraries do the work: a step and a position every 10 samples.
        REQUIRE(push(e, walk(0, 100)) == PN_OK);
        REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
        const auto out = e.poll_all();
        const auto pos = of_type(out, PN_REC_POSITION);
        REQUIRE(pos.size() == 10);
        CHECK(pos[9].position.pos_enu_m[0] == 10.0);
        CHECK(of_type(out, PN_REC_STEP).size() == 10);
    }
    for (const auto& name : used) CHECK_MESSAGE(!is_loaded(lazy_path(name)), name);  // closed with the engine
}

TEST_CASE(
    "the foot preset over the first-party plugins and the ten fixtures opens only the three foot libraries") {
    clear_marks();
    Engine e(read_text(std::string(PEDNAV_CONFIG_DIR) + "/foot.json"),
             {PEDNAV_PLUGIN_OUTPUT_DIR, fixture_dir("lazy_a"), fixture_dir("lazy_b")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    const json d = e.describe();
    std::set<std::string> opened;
    for (const auto& l : d["libraries"])
        if (l["opened"].get<bool>())
            opened.insert(fs::path(l["path"].get<std::string>()).filename().string());
    CHECK(opened ==
          std::set<std::string>{"libpnp_foot_stance.so", "libpnp_foot_strapdown.so", "libpnp_foot_ekf.so"});
    for (const auto& name : lazy_names()) {
        CAPTURE(name);
        CHECK_FALSE(marked(name));
        CHECK_FALSE(is_loaded(lazy_path(name)));
    }
    CHECK(d["rejected"].empty());
}

TEST_CASE("listing reads the manifests and opens nothing unless asked to") {
    clear_marks();
    const json listed = list_plugins({fixture_dir("lazy_a"), fixture_dir("lazy_b")}, 0);
    REQUIRE(listed.is_object());
    CHECK(listed["plugins"].size() == 30);
    CHECK(count_opened(listed) == 0);
    for (const auto& name : lazy_names()) CHECK_MESSAGE(!marked(name), name);

    const json opened = list_plugins({fixture_dir("lazy_a"), fixture_dir("lazy_b")}, PN_LIST_OPEN_LIBRARIES);
    REQUIRE(opened.is_object());
    CHECK(count_opened(opened) == 10);
    for (const auto& name : lazy_names()) {
        CAPTURE(name);
        CHECK(marked(name));
        CHECK_FALSE(is_loaded(lazy_path(name)));  // closed again when the listing is done
    }
    // The same plugins either way: the manifests say what the descriptors say.
    CHECK(listed["plugins"] == opened["plugins"]);
}

TEST_CASE(
    "a manifest that disagrees with its library: the library is refused when opened, each difference named") {
    struct Spoil {
        const char* what;
        void (*edit)(json&);
        std::vector<std::string> mentions;
    };
    const Spoil spoils[] = {
        {"a kind changed",
         [](json& m) { m["plugins"][0]["kind"] = "position_filter"; },
         {"org.pednav.test.lazy_a1.steps is a position_filter in the manifest, a step_detector in the "
          "library"}},
        {"a plugin missing",
         [](json& m) { m["plugins"].erase(1); },
         {"org.pednav.test.lazy_a1.attitude is in the library but not in the manifest"}},
        {"a plugin the library lacks",
         [](json& m) {
             json extra = m["plugins"][2];
             extra["id"] = "org.pednav.test.lazy_a1.extra";
             m["plugins"].push_back(extra);
         },
         {"org.pednav.test.lazy_a1.extra is in the manifest but not in the library"}},
        {"the library id",
         [](json& m) { m["library"]["id"] = "org.example.other"; },
         {"library id org.example.other in the manifest, org.pednav.test.lazy_a1 in the library"}},
    };
    for (const auto& spoil : spoils) {
        CAPTURE(spoil.what);
        clear_marks();
        const std::string dir = lazy_a1_copy("disagree");
        const std::string manifest = dir + "/libpnp_lazy_a1.json";
        json m = json::parse(read_text(manifest));
        spoil.edit(m);
        write_text(manifest, m.dump(2));

        // Read alone, the manifest is well formed: it is listed and nothing is opened.
        const json listed = list_plugins({dir}, 0);
        CHECK(listed["rejected"].empty());
        CHECK_FALSE(listed["plugins"].empty());
        CHECK_FALSE(marked("lazy_a1"));

        // Opened, the library is refused with every difference; none of its plugins is offered.
        const json d = list_plugins({dir}, PN_LIST_OPEN_LIBRARIES);
        const json r = entry_ending(d, "rejected", "/libpnp_lazy_a1.so");
        REQUIRE(!r.is_null());
        CHECK(r["status"] == "PN_E_ABI_MISMATCH");
        const std::string reason = r["reason"];
        CHECK_MESSAGE(contains(reason, "manifest " + manifest + " disagrees with the library"), reason);
        for (const auto& mention : spoil.mentions) CHECK_MESSAGE(contains(reason, mention), reason);
        CHECK(d["plugins"].empty());
        CHECK(d["libraries"].empty());

        // An engine that wants one of its plugins fails, naming why.
        Engine e(make_config({{"position_filter", "org.pednav.test.lazy_a1.filter"}}), {dir});
        CHECK(e.status() == PN_E_NOT_FOUND);
        CHECK_MESSAGE(contains(e.error().message, "its library was rejected: manifest"), e.error().message);
        CHECK(std::string(e.error().where) == "/pipelines/foot/position_filter/plugin");
    }
}

TEST_CASE("a manifest for another ABI major: the library is refused without being opened") {
    clear_marks();
    const std::string dir = lazy_a1_copy("abi_major");
    const std::string manifest = dir + "/libpnp_lazy_a1.json";
    json m = json::parse(read_text(manifest));
    m["abi_version"] = "2.0";
    write_text(manifest, m.dump(2));
    const json d = list_plugins({dir}, PN_LIST_OPEN_LIBRARIES);
    const json r = entry_ending(d, "rejected", "/libpnp_lazy_a1.so");
    REQUIRE(!r.is_null());
    CHECK(r["status"] == "PN_E_ABI_MISMATCH");
    CHECK_MESSAGE(contains(r["reason"], "ABI major 2, this engine speaks 1"), r["reason"]);
    CHECK_FALSE(marked("lazy_a1"));
    CHECK(d["plugins"].empty());
}

TEST_CASE("a library without a manifest is found, with a warning naming it, and opened only when needed") {
    clear_marks();
    const std::string dir = lazy_a1_copy("no_manifest", false);
    const std::string library = dir + "/libpnp_lazy_a1.so";
    std::vector<std::string> lines;
    auto log = [](void* user, int32_t level, const char*, const char* msg) {
        if (level == PNP_LOG_WARN) static_cast<std::vector<std::string>*>(user)->push_back(msg);
    };
    {
        // Every configured id is in lazy_b's manifests: the library is not opened.
        Engine e(lazy_config("lazy_b1", "lazy_b2", "lazy_b3"), {dir, fixture_dir("lazy_b")}, 0, {}, log,
                 &lines);
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        const json w = entry_ending(e.describe(), "load_warnings", "/libpnp_lazy_a1.so");
        REQUIRE(!w.is_null());
        CHECK_MESSAGE(contains(w["warning"], "no manifest libpnp_lazy_a1.json beside it"), w["warning"]);
        CHECK_FALSE(marked("lazy_a1"));
        CHECK_FALSE(is_loaded(library));
        REQUIRE(lines.size() == 1);
        CHECK(contains(lines[0], library));
    }
    {
        // Its id is in no manifest: it is opened and used.
        Engine e(lazy_config("lazy_a1", "lazy_b2", "lazy_b3"), {dir, fixture_dir("lazy_b")});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        CHECK(marked("lazy_a1"));
        CHECK(is_loaded(library));
        const json d = e.describe();
        const json l = entry_ending(d, "libraries", "/libpnp_lazy_a1.so");
        REQUIRE(!l.is_null());
        CHECK(l["opened"] == true);
        CHECK(l["manifest"].is_null());
        CHECK(!entry_ending(d, "load_warnings", "/libpnp_lazy_a1.so").is_null());
        REQUIRE(push(e, walk(0, 50)) == PN_OK);
        REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
        CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 5);
    }
}

TEST_CASE("a malformed manifest is refused naming the file and what is wrong; its library is still found") {
    struct Spoil {
        const char* what;
        std::string (*edit)(const std::string&);
        const char* mention;
    };
    const Spoil spoils[] = {
        {"not JSON", [](const std::string& t) { return t.substr(0, t.size() / 2); }, "not valid JSON"},
        {"another format",
         [](const std::string& t) {
             json m = json::parse(t);
             m["format"] = "pednav-plugin-manifest/2";
             return m.dump();
         },
         "/format: \"pednav-plugin-manifest/2\" is not \"pednav-plugin-manifest/1\""},
        {"a kind missing",
         [](const std::string& t) {
             json m = json::parse(t);
             m["plugins"][1].erase("kind");
             return m.dump();
         },
         "/plugins/1/kind: missing"},
        {"an unknown kind",
         [](const std::string& t) {
             json m = json::parse(t);
             m["plugins"][2]["kind"] = "gizmo";
             return m.dump();
         },
         "/plugins/2/kind: \"gizmo\" is not a plugin kind"},
        {"a bad ABI version",
         [](const std::string& t) {
             json m = json::parse(t);
             m["abi_version"] = "one";
             return m.dump();
         },
         "/abi_version: \"one\" is not MAJOR.MINOR"},
        {"another file",
         [](const std::string& t) {
             json m = json::parse(t);
             m["file"] = "libpnp_lazy_a2.so";
             return m.dump();
         },
         "describes libpnp_lazy_a2.so, not libpnp_lazy_a1.so"},
    };
    for (const auto& spoil : spoils) {
        CAPTURE(spoil.what);
        clear_marks();
        const std::string dir = lazy_a1_copy("malformed");
        const std::string manifest = dir + "/libpnp_lazy_a1.json";
        write_text(manifest, spoil.edit(read_text(manifest)));

        const json d = list_plugins({dir}, 0);
        REQUIRE(d.is_object());
        REQUIRE(d["rejected"].size() == 1);
        const json r = d["rejected"][0];
        CHECK(r["path"] == manifest);
        CHECK(r["status"] == "PN_E_BAD_INPUT");
        const std::string reason = r["reason"];
        CHECK_MESSAGE(contains(reason, manifest), reason);
        CHECK_MESSAGE(contains(reason, spoil.mention), reason);
        const json w = entry_ending(d, "load_warnings", "/libpnp_lazy_a1.so");
        REQUIRE(!w.is_null());
        CHECK_MESSAGE(contains(w["warning"], "its manifest libpnp_lazy_a1.json is refused"), w["warning"]);
        CHECK_FALSE(marked("lazy_a1"));

        // The library is found as one without a manifest.
        Engine e(make_config({{"step_detector", "org.pednav.test.lazy_a1.steps"}}), {dir});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        CHECK(marked("lazy_a1"));
    }
}

TEST_CASE("the same plugin id in two manifests: the second library is reported and never opened") {
    clear_marks();
    const std::string dir = lazy_a1_copy("duplicate");
    Engine e(make_config({{"step_detector", "org.pednav.test.lazy_a1.steps"}}), {fixture_dir("lazy_a"), dir});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    const json d = e.describe();
    REQUIRE(d["rejected"].size() == 3);  // its three plugins
    for (const auto& r : d["rejected"]) {
        CHECK(r["path"] == dir + "/libpnp_lazy_a1.so");
        CHECK_MESSAGE(contains(r["reason"], "already provided by " + lazy_path("lazy_a1")), r["reason"]);
    }
    CHECK(is_loaded(lazy_path("lazy_a1")));
    CHECK_FALSE(is_loaded(dir + "/libpnp_lazy_a1.so"));
}

TEST_CASE("a manifest without its library is ignored, with a warning") {
    const std::string dir = lazy_a1_copy("stray");
    fs::remove(dir + "/libpnp_lazy_a1.so");
    const json d = list_plugins({dir}, PN_LIST_OPEN_LIBRARIES);
    CHECK(d["plugins"].empty());
    CHECK(d["rejected"].empty());
    REQUIRE(d["load_warnings"].size() == 1);
    CHECK(d["load_warnings"][0]["path"] == dir + "/libpnp_lazy_a1.json");
    CHECK(contains(d["load_warnings"][0]["warning"], "without its library libpnp_lazy_a1.so"));
}
