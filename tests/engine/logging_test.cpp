// SPDX-License-Identifier: Apache-2.0
// Plugin code may log at any level from its library's init, from create,
// process and destroy: every line reaches the app's log callback attributed
// to its source, and lines at WARN and above are kept in the description.
// A warning logged from init or create used to crash the engine (the log path
// reached for the pipeline before it existed).
#include <doctest/doctest.h>

#include <set>
#include <utility>

#include "test_support.hpp"

using namespace pednav::test;

namespace {

struct LogLine {
    int32_t level;
    std::string source, msg;
};

void collect_log(void* user, int32_t level, const char* source, const char* msg) {
    static_cast<std::vector<LogLine>*>(user)->push_back({level, source, msg});
}

size_t count(const std::vector<LogLine>& lines, const std::string& source, const std::string& msg) {
    size_t n = 0;
    for (const auto& l : lines) n += l.source == source && l.msg == msg;
    return n;
}

const char* const kLevels[] = {"debug", "info", "warn", "error"};

}  // namespace

TEST_CASE("a plain C plugin logging at every level from init, create, process, latency_ns, flush, reset, destroy and deinit") {
    std::vector<LogLine> lines;
    const std::string config = make_config({{"position_filter", "org.pednav.test.logs_everywhere"}});
    {
        Engine e(config, {fixture_dir("logs_everywhere")}, 0, {}, &collect_log, &lines);
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        for (int level = 0; level < 4; ++level) {
            const std::string l = kLevels[level];
            CHECK(count(lines, "org.pednav.test.logs_everywhere", l + " at init") == 1);
            CHECK(count(lines, "foot/position_filter", l + " at create") == 1);
        }
        REQUIRE(push(e, walk(0, 21)) == PN_OK);  // the 21st waits for a later sample
        pn_error_t err = make_error();
        REQUIRE(pn_engine_flush(e.get(), &err) == PN_OK);
        CHECK(of_type(e.poll_all(), PN_REC_POSITION).size() == 2);  // one per 10 samples
        const size_t process_calls = count(lines, "foot/position_filter", "debug at process");
        CHECK(process_calls == 21);  // one call per sample time
        CHECK(count(lines, "foot/position_filter", "error at process") == process_calls);

        // WARN and ERROR lines are kept, attributed; DEBUG and INFO are not.
        const auto d = e.describe();
        std::set<std::string> warnings;
        for (const auto& w : d["warnings"]) warnings.insert(w.get<std::string>());
        CHECK(warnings.count("org.pednav.test.logs_everywhere: warn at init") == 1);
        CHECK(warnings.count("foot/position_filter: error at create") == 1);
        CHECK(warnings.count("foot/position_filter: warn at process") == 1);
        CHECK(warnings.count("foot/position_filter: info at create") == 0);
        // init, create, latency_ns (read once when the pipeline is wired), flush, and each process call.
        for (const char* l : kLevels) {
            CHECK(count(lines, "foot/position_filter", std::string(l) + " at latency_ns") == 1);
            CHECK(count(lines, "foot/position_filter", std::string(l) + " at flush") == 1);
        }
        CHECK(d["counters"]["warnings"].get<uint64_t>() == 2 + 2 + 2 + 2 + 2 * process_calls);
        CHECK(count(lines, "foot/position_filter", "warn at destroy") == 0);

        // A reset calls reset and reads the look-ahead again; both log at every level.
        REQUIRE(pn_engine_reset(e.get(), &err) == PN_OK);
        for (const char* l : kLevels) {
            CHECK(count(lines, "foot/position_filter", std::string(l) + " at reset") == 1);
            CHECK(count(lines, "foot/position_filter", std::string(l) + " at latency_ns") == 2);
        }
        CHECK(count(lines, "org.pednav.test.logs_everywhere", "warn at deinit") == 0);
    }
    for (const char* l : kLevels) {
        CHECK(count(lines, "foot/position_filter", std::string(l) + " at destroy") == 1);
        CHECK(count(lines, "org.pednav.test.logs_everywhere", std::string(l) + " at deinit") == 1);
    }
}

TEST_CASE("instances already created are destroyed when the pipeline cannot be built") {
    // The step detector declares a look-ahead of 1000 samples x 0.1 s = 100 s,
    // over the 60 s a stage may hold back: the scheduler refuses the pipeline
    // after both instances exist. The logging position filter must be destroyed.
    std::vector<LogLine> lines;
    const std::string config =
        make_config({{"step_detector", "org.pednav.test.counting_steps", {{"latency_samples", 1000}, {"sample_period_s", 0.1}}},
                     {"position_filter", "org.pednav.test.logs_everywhere"}});
    Engine e(config, {fixture_dir("good"), fixture_dir("logs_everywhere")}, 0, {}, &collect_log, &lines);
    CHECK(e.status() == PN_E_INVALID_CONFIG);
    CHECK(e.get() == nullptr);
    CHECK(std::string(e.error().where) == "/pipelines/foot/step_detector");
    CHECK_MESSAGE(contains(e.error().message, "look-ahead of 100 s, outside [0, 60] s"), e.error().message);
    CHECK(count(lines, "foot/position_filter", "debug at create") == 1);
    CHECK(count(lines, "foot/position_filter", "debug at destroy") == 1);
}
