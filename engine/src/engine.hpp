// SPDX-License-Identifier: Apache-2.0
// The object behind pn_engine_t: loads plugins, builds the pipeline of the
// configured mount, validates app inputs, keeps what the app set (start,
// attitude, origin, map) to give it again after a reset, and describes itself.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>

#include "config.hpp"
#include "diagnostics.hpp"
#include "loader.hpp"
#include "origin.hpp"
#include "scheduler.hpp"

namespace pednav::engine {

class Engine {
public:
    // Throws ConfigProblem (status, where, message) when the engine cannot be
    // built; everything created so far is destroyed then.
    explicit Engine(const pn_engine_create_info_t& info);
    ~Engine();

    pn_status_t push(const pn_record_header_t* record, pn_error_t* err);
    pn_status_t flush(pn_error_t* err);
    pn_status_t reset(pn_error_t* err);

    // What the app sets (app_settings.cpp).
    pn_status_t set_start(const double pos_enu_m[3], double heading_deg, pn_error_t* err);
    pn_status_t set_attitude(const double q_enu_from_body[4], pn_error_t* err);
    pn_status_t set_origin(const pn_geo_point_t& origin, pn_error_t* err);
    pn_status_t load_map(const std::string& format, const void* bytes, size_t size, pn_error_t* err);
    pn_status_t reconfigure(const std::string& stage, const std::string& params_json, pn_error_t* err);
    pn_status_t set_output_mask(uint64_t mask);

    const GeoOrigin& origin() const { return origin_; }
    Scheduler& scheduler() { return *scheduler_; }
    const Scheduler& scheduler() const { return *scheduler_; }
    std::string describe_json() const;

private:
    // Plugins subtract windows from times and add look-aheads to them; a time
    // within 2^62 ns (146 years) of zero leaves them that room without overflow.
    static constexpr int64_t kMaxAbsTimeNs = int64_t{1} << 62;
    bool input_fine(const pn_record_header_t* record) const;
    pn_status_t check_input(const pn_record_header_t* record, pn_error_t* err);
    // PN_OK, or the stage failure of the last push or flush, in *err.
    pn_status_t stage_failure_status(pn_error_t* err) {
        return scheduler_->has_failure() ? report_stage_failure(err) : PN_OK;
    }
    pn_status_t report_stage_failure(pn_error_t* err);  // out of line: not on the per-sample path
    pn_status_t report_stopped(pn_error_t* err) const;  // PN_E_BAD_STATE naming the stage that stopped it
    void take_origin_from_fix(const pn_gnss_t& fix);

    std::vector<std::unique_ptr<Stage>> plan_stages();
    void create_instances(std::vector<std::unique_ptr<Stage>>& stages);
    void load_config_map();
    // Gives the fresh plugins of a reset what the app set.
    pn_status_t reapply_settings(pn_error_t* err);
    Stage* stage_for_role(Role role) const;
    const pnp_map_matcher_ops_t* map_loader(Stage** stage) const;
    static std::string no_map_loader_reason(const Stage* stage);
    pn_status_t bad_state_after_push(const char* what, pn_error_t* err) const;

    // Declared in the order they must outlive each other: plugins may log
    // and read the origin from their library's init to their destroy, and
    // libraries are unloaded only after every instance is gone.
    Diagnostics diagnostics_;
    GeoOrigin origin_;
    std::vector<std::unique_ptr<HostContext>> library_hosts_;  // what each library's init got
    std::unique_ptr<Loader> loader_;
    EngineConfig config_;
    std::unique_ptr<Scheduler> scheduler_;

    int64_t last_t_ns_[PN_REC_TYPE_COUNT];
    ValuesCheck input_values_ok_[PN_REC_TYPE_COUNT];  // values_check_for each type
    int64_t last_any_t_ns_ = INT64_MIN;
    uint64_t rejected_inputs_ = 0;
    bool pushed_ = false;  // a record was accepted since create or the last reset

    // What the app set, given again after a reset.
    struct Start {
        bool set = false;
        double pos_enu_m[3] = {0, 0, 0};
        double heading_deg = 0;
    } start_;
    struct Attitude {
        bool set = false;
        double q_enu_from_body[4] = {1, 0, 0, 0};
    } attitude_;
    struct Map {
        std::string format;
        std::vector<unsigned char> bytes;  // empty: no map
        std::string label;                 // "the app" or the config's path
    } map_;
};

// Fills a caller's pn_error_t (if any).
void set_error(pn_error_t* err, pn_status_t code, const std::string& where, const std::string& message,
               int32_t detail = 0);

}  // namespace pednav::engine
