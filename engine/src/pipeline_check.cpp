// SPDX-License-Identifier: Apache-2.0
#include "pipeline_check.hpp"

#include <cstring>
#include <string>

#include "record_checks.hpp"

namespace pednav::engine {

pn_record_type_t record_type_from_name(const char* name) {
    for (pn_record_type_t t = 1; t < PN_REC_TYPE_COUNT; ++t)
        if (std::strcmp(record_type_name(t), name) == 0) return t;
    return 0;
}

namespace {

std::string type_list(uint64_t mask) {
    std::string s;
    for (pn_record_type_t t = 1; t < PN_REC_TYPE_COUNT; ++t)
        if (mask & PN_REC_MASK(t)) s += (s.empty() ? "" : ", ") + std::string(record_type_name(t));
    return s.empty() ? "nothing" : s;
}

std::string producers(const std::vector<std::unique_ptr<Stage>>& stages, size_t before) {
    if (before == 0) return "it is the first stage";
    std::string s;
    for (size_t i = 0; i < before; ++i)
        s += (s.empty() ? "" : "; ") + stages[i]->instance_name + " (" + stages[i]->plugin_id + ") produces " +
             type_list(stages[i]->descriptor->produces);
    return s;
}

}  // namespace

void check_pipeline_needs(const std::vector<std::unique_ptr<Stage>>& stages) {
    uint64_t upstream = 0;
    for (size_t k = 0; k < stages.size(); ++k) {
        const Stage& s = *stages[k];
        for (const char* const* f = s.descriptor->features; f && *f; ++f) {
            if (std::strncmp(*f, "needs:", 6) != 0) continue;
            const char* name = *f + 6;
            const pn_record_type_t type = record_type_from_name(name);
            if (type == 0)
                throw ConfigProblem{PN_E_INVALID_CONFIG, s.pointer + "/plugin",
                                    s.instance_name + " (" + s.plugin_id + ") needs \"" + name +
                                        "\" records, a type this engine does not know"};
            if (kInputTypes & PN_REC_MASK(type)) continue;  // the app may push it
            if (upstream & PN_REC_MASK(type)) continue;
            throw ConfigProblem{PN_E_INVALID_CONFIG, s.pointer + "/plugin",
                                s.instance_name + " (" + s.plugin_id + ") needs " + name +
                                    " records, which no earlier stage of the pipeline produces (" +
                                    producers(stages, k) + ")"};
        }
        upstream |= s.descriptor->produces;
    }
}

}  // namespace pednav::engine
