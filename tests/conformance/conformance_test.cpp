// SPDX-License-Identifier: Apache-2.0
// Conformance suite stamped onto every first-party plugin: each plugin the
// loader finds in the first-party plugin directory is put into its role of
// the preset pipeline of each mount it declares ("mount:<m>" feature), and the
// pipeline is run through the C API on a simulated walk of that mount. Every
// plugin must give finite, time-ordered outputs, unit quaternions and
// symmetric positive semi-definite covariances; reset and a second engine must
// reproduce the outputs bit for bit; an unknown parameter must be rejected with
// its key named.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav/pn_engine.h>
#include <pednav_sim/simulate.hpp>

#include "test_support.hpp"

namespace {

using nlohmann::json;
using pednav::test::Engine;
using pednav::test::make_error;

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// An engine on the first-party plugins.
struct FirstParty : Engine {
    explicit FirstParty(const std::string& config)
        : Engine(config, {PEDNAV_PLUGIN_OUTPUT_DIR}, 4096 /* polled after every push */) {}
};

// Every output of a run, as raw bytes for bit-exact comparison.
std::vector<std::string> run(pn_engine_t* e, const std::vector<const pn_record_header_t*>& records) {
    const uint64_t all = PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_STEP) |
                         PN_REC_MASK(PN_REC_ATTITUDE) | PN_REC_MASK(PN_REC_GAIT_PHASE);
    pn_engine_set_output_mask(e, all);
    std::vector<std::string> out;
    pn_output_t o;
    auto drain = [&] {
        while (pn_engine_poll(e, &o) == PN_OK) out.emplace_back(reinterpret_cast<const char*>(&o), o.header.struct_size);
    };
    pn_error_t err = make_error();
    for (const auto* r : records) {
        const pn_status_t s = pn_engine_push(e, r, &err);
        INFO(err.where << ": " << err.message);
        REQUIRE(s == PN_OK);
        drain();
    }
    REQUIRE(pn_engine_flush(e, &err) == PN_OK);
    drain();
    return out;
}

bool symmetric_psd(const double* c) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::fabs(c[3 * i + j] - c[3 * j + i]) > 1e-9 * (1 + std::fabs(c[3 * i + j]))) return false;
    // Sylvester on the leading minors, with a small tolerance for round-off.
    const double m1 = c[0];
    const double m2 = c[0] * c[4] - c[1] * c[3];
    const double m3 = c[0] * (c[4] * c[8] - c[5] * c[7]) - c[1] * (c[3] * c[8] - c[5] * c[6]) +
                      c[2] * (c[3] * c[7] - c[4] * c[6]);
    const double scale = std::max({std::fabs(c[0]), std::fabs(c[4]), std::fabs(c[8]), 1e-30});
    return m1 >= -1e-12 * scale && m2 >= -1e-9 * scale * scale && m3 >= -1e-9 * scale * scale * scale;
}

void check_outputs(const std::vector<std::string>& outputs) {
    int64_t last_t[PN_REC_TYPE_COUNT];
    for (auto& t : last_t) t = INT64_MIN;
    size_t positions = 0;
    for (const auto& bytes : outputs) {
        pn_output_t o;
        std::memcpy(&o, bytes.data(), bytes.size());
        const uint32_t type = o.header.type;
        REQUIRE(type < PN_REC_TYPE_COUNT);
        CHECK(o.header.t_ns >= last_t[type]);
        last_t[type] = o.header.t_ns;
        if (type == PN_REC_POSITION) {
            ++positions;
            for (double v : o.position.pos_enu_m) REQUIRE(std::isfinite(v));
            REQUIRE(symmetric_psd(o.position.cov_enu_m2));
        } else if (type == PN_REC_ATTITUDE) {
            const double* q = o.attitude.q_enu_from_body;
            REQUIRE(std::fabs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1) < 1e-6);
            REQUIRE(symmetric_psd(o.attitude.cov_attitude_rad2));
        } else if (type == PN_REC_STRIDE) {
            REQUIRE(symmetric_psd(o.stride.cov_displacement_m2));
            REQUIRE(o.stride.length_m >= 0);
        }
    }
    CHECK(positions > 0);
}

struct Candidate {
    std::string id, kind, mount;
};

std::string role_of_kind(const std::string& kind) { return kind; }  // kinds and roles share names

}  // namespace

TEST_CASE("every first-party plugin passes the conformance suite in each mount it declares") {
    // Discover the plugins through an engine on the foot preset.
    const std::string foot_preset = read_file(std::string(PEDNAV_CONFIG_DIR) + "/foot.json");
    REQUIRE(!foot_preset.empty());
    const FirstParty probe(foot_preset);
    INFO(probe.error().where << ": " << probe.error().message);
    REQUIRE(probe.status() == PN_OK);
    const json d = probe.describe();
    REQUIRE(d.is_object());
    CHECK(d["rejected"].empty());
    std::vector<Candidate> candidates;
    for (const auto& p : d["plugins"]) {
        const size_t before = candidates.size();
        for (const auto& f : p["features"]) {
            const std::string tag = f.get<std::string>();
            if (tag.rfind("mount:", 0) == 0)
                candidates.push_back({p["id"].get<std::string>(), p["kind"].get<std::string>(), tag.substr(6)});
        }
        if (candidates.size() == before)  // no mount declared: any mount
            for (const char* m : {"foot", "chest", "handheld", "waist"})
                candidates.push_back({p["id"].get<std::string>(), p["kind"].get<std::string>(), m});
    }
    REQUIRE(candidates.size() >= 4);

    std::map<std::string, pednav::sim::SimOutput> walks;  // one simulated walk per mount, shared by its candidates
    size_t tested = 0;
    for (const auto& c : candidates) {
        // A plugin made for a mount runs in that mount's preset; a mount without
        // one is a failure, not a pass without running.
        const std::string preset_path = std::string(PEDNAV_CONFIG_DIR) + "/" + c.mount + ".json";
        const std::string preset_text = read_file(preset_path);
        if (preset_text.empty()) {
            FAIL_CHECK(c.id << " declares mount:" << c.mount << " but there is no preset " << preset_path);
            continue;
        }
        CAPTURE(c.id);
        CAPTURE(c.mount);
        json preset = json::parse(preset_text);
        json& stage = preset["pipelines"][c.mount][role_of_kind(c.kind)];
        if (!stage.is_object() || stage["plugin"] != c.id) stage = {{"plugin", c.id}, {"params", json::object()}};
        preset["mount"] = c.mount;

        auto walk = walks.find(c.mount);
        if (walk == walks.end()) {
            pednav::sim::SimOptions so;
            so.mount = c.mount;
            so.rate_hz = 200;
            so.seed = 11;
            walk = walks.emplace(c.mount, pednav::sim::simulate(pednav::sim::builtin_route("corridor_loop"), so)).first;
        }
        const auto records = walk->second.records();

        const FirstParty a(preset.dump());
        INFO(a.error().where << ": " << a.error().message);
        REQUIRE(a.status() == PN_OK);
        const auto first = run(a.get(), records);
        check_outputs(first);

        // Reset gives the state right after create: the same outputs again.
        pn_error_t err = make_error();
        REQUIRE(pn_engine_reset(a.get(), &err) == PN_OK);
        CHECK(run(a.get(), records) == first);

        // A second engine on the same input: bit-identical.
        const FirstParty b(preset.dump());
        REQUIRE(b.status() == PN_OK);
        CHECK(run(b.get(), records) == first);

        // Defaults alone are a valid configuration.
        json defaults = preset;
        defaults["pipelines"][c.mount][role_of_kind(c.kind)]["params"] = json::object();
        CHECK(FirstParty(defaults.dump()).status() == PN_OK);

        // An unknown parameter is rejected with its key named.
        json typo = preset;
        typo["pipelines"][c.mount][role_of_kind(c.kind)]["params"]["no_such_parameter"] = 1;
        const FirstParty t(typo.dump());
        CHECK(t.get() == nullptr);
        CHECK(t.error().code == PN_E_INVALID_CONFIG);
        CHECK(std::string(t.error().where) ==
              "/pipelines/" + c.mount + "/" + role_of_kind(c.kind) + "/params/no_such_parameter");
        ++tested;
    }
    CHECK(tested >= 4);
}
