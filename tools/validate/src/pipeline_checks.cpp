// SPDX-License-Identifier: Apache-2.0
// The checks that run a plugin in its pipeline on the simulated walk.
#include <map>

#include "checks.hpp"
#include "engine_run.hpp"

namespace pednav::validate {

namespace {

// Index of the first output that differs, or -1 when the runs agree.
long first_difference(const std::vector<OutputBytes>& a, const std::vector<OutputBytes>& b) {
    const size_t n = std::min(a.size(), b.size());
    for (size_t i = 0; i < n; ++i)
        if (a[i] != b[i]) return static_cast<long>(i);
    return a.size() == b.size() ? -1 : static_cast<long>(n);
}

std::string difference_text(const std::vector<OutputBytes>& a, const std::vector<OutputBytes>& b, long i) {
    return "output " + std::to_string(i) + " of " + std::to_string(a.size()) + " differs (" + std::to_string(b.size()) +
           " outputs the second time)";
}

// Runs the walk, resets, runs it again; empty on success, else what failed.
std::string run_reset_run(EngineRun& e, const Placement& p, std::vector<OutputBytes>& first,
                          std::vector<OutputBytes>& second) {
    std::string problem = e.run(*p.records, first);
    if (problem.empty()) problem = e.reset();
    if (problem.empty()) problem = e.run(*p.records, second);
    return problem;
}

}  // namespace

nlohmann::json lifecycle_check(const Placement& p) {
    EngineRun e(p.config, p.plugin_dirs);
    if (!e.created()) return check_result(false, "create failed: " + e.error_text());
    std::vector<OutputBytes> first, second;
    const std::string problem = run_reset_run(e, p, first, second);
    e.destroy();
    nlohmann::json detail = {{"outputs", first.size()}, {"outputs_after_reset", second.size()}};
    return check_result(problem.empty(), problem, detail);
}

nlohmann::json outputs_check(const Placement& p) {
    EngineRun e(p.config, p.plugin_dirs);
    if (!e.created()) return check_result(false, "create failed: " + e.error_text());
    std::vector<OutputBytes> outputs;
    const std::string problem = e.run(*p.records, outputs);
    const OutputSummary s = check_outputs(outputs);
    const nlohmann::json detail = {{"outputs", s.count},       {"positions", s.positions}, {"strides", s.strides},
                                   {"steps", s.steps},         {"attitudes", s.attitudes}, {"gait_phases", s.gait_phases}};
    const auto caught = e.misbehaving();
    if (!caught.empty()) return check_result(false, "the engine caught: " + caught.front(), detail);
    if (!s.problems.empty()) return check_result(false, s.problems.front(), detail);
    if (!problem.empty()) return check_result(false, problem, detail);
    if (s.positions == 0) return check_result(false, "the pipeline gave no position", detail);
    return check_result(true, "", detail);
}

nlohmann::json reset_check(const Placement& p) {
    EngineRun e(p.config, p.plugin_dirs);
    if (!e.created()) return check_result(false, "create failed: " + e.error_text());
    std::vector<OutputBytes> first, again;
    const std::string problem = run_reset_run(e, p, first, again);
    if (!problem.empty()) return check_result(false, problem);
    const long d = first_difference(first, again);
    return check_result(d < 0, "after reset, " + difference_text(first, again, d), {{"outputs", first.size()}});
}

nlohmann::json determinism_check(const Placement& p) {
    std::vector<OutputBytes> a_out, b_out;
    std::string problem;
    {
        EngineRun a(p.config, p.plugin_dirs);
        if (!a.created()) return check_result(false, "create failed: " + a.error_text());
        problem = a.run(*p.records, a_out);
    }
    if (problem.empty()) {
        EngineRun b(p.config, p.plugin_dirs);
        if (!b.created()) return check_result(false, "second create failed: " + b.error_text());
        problem = b.run(*p.records, b_out);
    }
    if (!problem.empty()) return check_result(false, problem);
    const long d = first_difference(a_out, b_out);
    return check_result(d < 0, "a second engine on the same input: " + difference_text(a_out, b_out, d),
                        {{"outputs", a_out.size()}});
}

nlohmann::json logging_check(const Placement& p) {
    EngineRun e(p.config, p.plugin_dirs);
    if (!e.created()) return check_result(false, "create failed: " + e.error_text());
    std::vector<OutputBytes> outputs;
    std::string problem = e.run(*p.records, outputs);
    if (problem.empty()) problem = e.reset();
    e.destroy();
    // Lines of this instance (its name) or of its library's init, per phase.
    const std::string instance = p.mount + "/" + p.role;
    std::map<std::string, size_t> per_phase;
    for (const char* phase : {"create", "process", "flush", "reset", "destroy"}) per_phase[phase] = 0;
    size_t unattributed = 0;
    for (const auto& l : e.log()) {
        if (l.source == instance) ++per_phase[l.phase];
        if (l.source.empty()) ++unattributed;
    }
    nlohmann::json detail = {{"instance", instance}, {"lines", per_phase}};
    if (!problem.empty()) return check_result(false, problem, detail);
    if (unattributed) return check_result(false, std::to_string(unattributed) + " log lines without a source", detail);
    return check_result(true, "", detail);
}

}  // namespace pednav::validate
