// SPDX-License-Identifier: Apache-2.0
// The validator's own tests (tools/validate, `pednav validate`): its building
// blocks, and every deliberately broken fixture plugin failing the check it
// breaks, for the reason it breaks it, while the checks it keeps still pass.
// That every first-party plugin passes is the ctest conformance.<plugin>.
#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <pednav_validate/isolated.hpp>
#include <pednav_validate/output_checks.hpp>
#include <pednav_validate/validate.hpp>

namespace {

namespace fs = std::filesystem;
using pednav::validate::Options;
using pednav::validate::Report;
using pednav::validate::validate_library;

std::string fixture(const std::string& name) {
    return std::string(PEDNAV_TEST_PLUGIN_DIR) + "/" + name + "/libpnp_" + name + ".so";
}

Options options(double timeout_s = 60) {
    Options o;
    o.plugin_dirs = {PEDNAV_PLUGIN_OUTPUT_DIR};
    o.config_dir = PEDNAV_CONFIG_DIR;
    o.timeout_s = timeout_s;
    return o;
}

bool passed(const Report& r, const std::string& check) {
    bool seen = false;
    for (const auto& c : r.checks)
        if (c.check == check) {
            seen = true;
            if (!c.passed) return false;
        }
    return seen;
}

std::string reason(const Report& r, const std::string& check) {
    const auto* c = r.failed(check);
    return c ? c->reason : std::string("(the check did not fail)");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("symmetric_psd: identity, zero and a correlated pair pass; asymmetric, indefinite and NaN fail") {
    using pednav::validate::symmetric_psd;
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double zero[9] = {};
    const double correlated[9] = {4, 1.9, 0, 1.9, 1, 0, 0, 0, 2};  // |rho| = 0.95
    const double asymmetric[9] = {1, 0.5, 0, 0.4, 1, 0, 0, 0, 1};
    const double indefinite[9] = {1, 2, 2, 2, 1, 2, 2, 2, 1};  // eigenvalues 5, -1, -1
    const double negative_last[9] = {1, 0, 0, 0, 1, 0, 0, 0, -1e-3};
    const double zero_pivot[9] = {0, 0, 0, 0, -1, 0, 0, 0, 1};  // leading minors 0, 0, 0 but not PSD
    const double nan[9] = {1, 0, 0, 0, NAN, 0, 0, 0, 1};
    CHECK(symmetric_psd(identity));
    CHECK(symmetric_psd(zero));
    CHECK(symmetric_psd(correlated));
    CHECK_FALSE(symmetric_psd(asymmetric));
    CHECK_FALSE(symmetric_psd(indefinite));
    CHECK_FALSE(symmetric_psd(negative_last));
    CHECK_FALSE(symmetric_psd(zero_pivot));
    CHECK_FALSE(symmetric_psd(nan));
}

TEST_CASE("run_isolated reports a result, a crash, an abort, an exit, a hang and an exception") {
    using pednav::validate::run_isolated;
    const auto ok = run_isolated([] { return nlohmann::json{{"answer", 42}}; }, 10);
    CHECK(ok.finished);
    CHECK(ok.result["answer"] == 42);

    const auto segv = run_isolated([]() -> nlohmann::json { raise(SIGSEGV); return {}; }, 10);
    CHECK_FALSE(segv.finished);
    CHECK(contains(segv.failure, "killed by signal 11"));

    const auto aborted = run_isolated([]() -> nlohmann::json { std::abort(); }, 10);
    CHECK(contains(aborted.failure, "killed by signal 6"));

    const auto exited = run_isolated([]() -> nlohmann::json { _exit(7); }, 10);
    CHECK(exited.failure == "exited with status 7 before reporting");

    const auto quiet = run_isolated([]() -> nlohmann::json { _exit(0); }, 10);
    CHECK(contains(quiet.failure, "exited 0 without a complete result"));

    const auto hung = run_isolated([]() -> nlohmann::json { for (;;) pause(); }, 0.5);
    CHECK(hung.failure == "timed out after 0.5 s (killed)");

    const auto threw = run_isolated([]() -> nlohmann::json { throw std::runtime_error("no luck"); }, 10);
    CHECK(threw.finished);
    CHECK(threw.result["exception"] == "no luck");
}

TEST_CASE("a plugin that segfaults in process fails the checks that process, with signal 11") {
    const Report r = validate_library(fixture("segfault_in_process"), options());
    CHECK(passed(r, "load"));
    CHECK(passed(r, "manifest"));
    CHECK(passed(r, "params"));  // create alone is fine
    for (const char* check : {"lifecycle", "outputs", "reset", "determinism", "logging"})
        CHECK_MESSAGE(contains(reason(r, check), "killed by signal 11 (Segmentation fault)"), check);
    CHECK_FALSE(r.passed());
}

TEST_CASE("a plugin that aborts in create fails every plugin check with signal 6") {
    const Report r = validate_library(fixture("abort_in_create"), options());
    CHECK(passed(r, "load"));
    for (const char* check : {"lifecycle", "outputs", "reset", "determinism", "params", "logging"})
        CHECK_MESSAGE(contains(reason(r, check), "killed by signal 6 (Aborted)"), check);
}

TEST_CASE("a plugin that hangs in process is killed at the timeout") {
    const Report r = validate_library(fixture("hangs"), options(2));
    CHECK(passed(r, "params"));
    CHECK(reason(r, "lifecycle") == "timed out after 2 s (killed)");
    CHECK(reason(r, "determinism") == "timed out after 2 s (killed)");
}

TEST_CASE("a plugin that calls _exit in process fails with its status") {
    const Report r = validate_library(fixture("exits"), options());
    CHECK(reason(r, "lifecycle") == "exited with status 3 before reporting");
}

TEST_CASE("a non-PSD covariance fails the outputs check with the engine's finding, and the run") {
    // The engine refuses the record itself (PN_E_NUMERIC, like a NaN), so the
    // checks that run the pipeline fail too; those that do not, pass.
    const Report r = validate_library(fixture("non_psd_covariance"), options());
    CHECK(contains(reason(r, "outputs"), "the engine caught: foot/position_filter: misbehaving: emitted a position "
                                         "record at t=0.045000 s whose cov_enu_m2[1] is 2 (a correlation above 1: "
                                         "not positive semi-definite)"));
    CHECK(contains(reason(r, "lifecycle"), "PN_E_NUMERIC"));
    for (const char* check : {"load", "manifest", "params"}) CHECK_MESSAGE(passed(r, check), check);
}

TEST_CASE("outputs going back in time fail the outputs check with the engine's finding") {
    const Report r = validate_library(fixture("back_in_time"), options());
    const std::string why = reason(r, "outputs");
    CHECK(contains(why, "the engine caught: foot/position_filter: misbehaving: emitted a position record at t="));
    CHECK(contains(why, "before its previous position"));
    for (const char* check : {"lifecycle", "reset", "determinism", "params"}) CHECK_MESSAGE(passed(r, check), check);
}

TEST_CASE("a reset that keeps state fails the reset check, not determinism") {
    const Report r = validate_library(fixture("reset_not_idempotent"), options());
    const std::string why = reason(r, "reset");
    CHECK(contains(why, "after reset, output "));
    CHECK(contains(why, " differs"));
    CHECK(passed(r, "determinism"));
    CHECK(passed(r, "outputs"));
}

TEST_CASE("a plugin that accepts an unknown parameter fails the params check naming it") {
    const Report r = validate_library(fixture("accepts_bad_param"), options());
    CHECK(reason(r, "params") == "accepted no_such_parameter = 1 (unknown key)");
    for (const char* check : {"lifecycle", "outputs", "reset", "determinism", "logging"})
        CHECK_MESSAGE(passed(r, check), check);
}

TEST_CASE("the older fixtures fail for their own reasons") {
    const Report nan = validate_library(fixture("emits_nan"), options());
    CHECK(contains(reason(nan, "outputs"), "whose pos_enu_m[0] is nan"));
    CHECK(contains(reason(nan, "lifecycle"), "PN_E_NUMERIC"));

    const Report wrong_major = validate_library(fixture("wrong_major"), options());
    CHECK(reason(wrong_major, "load") ==
          "exports pnp_entry_v2 (another ABI major) but not pnp_entry_v1; this engine speaks ABI major 1 "
          "(PN_E_ABI_MISMATCH)");
    CHECK(wrong_major.checks.size() == 2);  // nothing is run from a library that does not load

    const Report too_small = validate_library(fixture("too_small"), options());
    CHECK(contains(reason(too_small, "load"), "below the minimum"));
    CHECK(contains(reason(too_small, "manifest"), "cannot be read"));

    Options chest = options();
    chest.mount = "chest";
    const Report throws = validate_library(fixture("throws"), chest);
    CHECK(contains(reason(throws, "lifecycle"), "plugin threw: fixture failure at sample 50"));
}

TEST_CASE("logging from create, process and destroy reaches the app, attributed to the instance") {
    const Report r = validate_library(fixture("logs_everywhere"), options());
    const pednav::validate::CheckResult* logging = nullptr;
    for (const auto& c : r.checks)
        if (c.check == "logging") logging = &c;
    REQUIRE(logging != nullptr);
    CHECK(logging->passed);
    CHECK(logging->detail["instance"] == "foot/position_filter");
    CHECK(logging->detail["lines"]["create"] == 8);  // one line per level from create and from latency_ns, asked at create
    CHECK(logging->detail["lines"]["process"].get<int>() >= 4);
    CHECK(logging->detail["lines"]["destroy"] == 4);
    // Its params are not checked by a schema nor by itself; it has no manifest.
    CHECK(reason(r, "params") == "accepted no_such_parameter = 1 (unknown key)");
    CHECK(contains(reason(r, "manifest"), "cannot be read"));
}

TEST_CASE("a manifest that disagrees with the library, or is stale, fails the manifest check") {
    const fs::path dir = fs::path(PEDNAV_VALIDATE_WORK_DIR) / "manifests";
    fs::remove_all(dir);
    fs::create_directories(dir / "disagrees");
    fs::create_directories(dir / "stale");
    const std::string lib = "libpnp_non_psd_covariance";
    const fs::path from = fs::path(PEDNAV_TEST_PLUGIN_DIR) / "non_psd_covariance";
    std::ifstream in(from / (lib + ".json"));
    nlohmann::json manifest = nlohmann::json::parse(in);
    for (const char* sub : {"disagrees", "stale"}) fs::copy_file(from / (lib + ".so"), dir / sub / (lib + ".so"));
    nlohmann::json disagrees = manifest, stale = manifest;
    disagrees["plugins"][0]["kind"] = "map_matcher";
    stale["plugins"][0]["description"] = "an older description";
    std::ofstream(dir / "disagrees" / (lib + ".json")) << disagrees.dump(2);
    std::ofstream(dir / "stale" / (lib + ".json")) << stale.dump(2);

    const Report d = validate_library((dir / "disagrees" / (lib + ".so")).string(), options());
    CHECK(contains(reason(d, "manifest"), "is a map_matcher in the manifest, a position_filter in the library"));
    const Report s = validate_library((dir / "stale" / (lib + ".so")).string(), options());
    CHECK(contains(reason(s, "manifest"), "plugin org.pednav.test.non_psd_covariance member \"description\" differs"));
}
