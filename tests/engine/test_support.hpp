// SPDX-License-Identifier: Apache-2.0
// Helpers for the engine tests. Everything goes through the public C API
// (pn_engine.h); nlohmann_json only parses pn_engine_describe's output.
#pragma once

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>
#include <nlohmann/json.hpp>

namespace pednav::test {

#ifdef PEDNAV_TEST_PLUGIN_DIR
// <build>/test-plugins/<name>: one fixture library per directory.
inline std::string fixture_dir(const std::string& name) {
    return std::string(PEDNAV_TEST_PLUGIN_DIR) + "/" + name;
}
#endif

inline pn_error_t make_error() {
    pn_error_t e;
    std::memset(&e, 0, sizeof e);
    e.struct_size = sizeof e;
    return e;
}

// One stage of a config: role -> {"plugin": id, "params": params}.
struct StageSpec {
    std::string role;
    std::string plugin;
    nlohmann::json params = nlohmann::json::object();
};

inline std::string make_config(const std::vector<StageSpec>& stages, const std::string& mount = "foot") {
    nlohmann::json pipe = nlohmann::json::object();
    for (const auto& s : stages) pipe[s.role] = {{"plugin", s.plugin}, {"params", s.params}};
    nlohmann::json doc = {{"format", "pednav-config/1"}, {"mount", mount}, {"pipelines", {{mount, pipe}}}};
    return doc.dump();
}

// RAII owner of an engine created from a config and fixture directories.
class Engine {
public:
    Engine(const std::string& config, const std::vector<std::string>& dirs, uint32_t queue_capacity = 0,
           const std::vector<const pnp_library_t*>& static_libraries = {}, pn_log_fn log = nullptr,
           void* log_user = nullptr)
        : dirs_(dirs), err_(make_error()) {
        for (const auto& d : dirs_) dir_ptrs_.push_back(d.c_str());
        pn_engine_create_info_t info;
        std::memset(&info, 0, sizeof info);
        info.abi_version = PN_ABI_VERSION;
        info.struct_size = sizeof info;
        info.config_json = config.c_str();
        info.config_len = config.size();
        info.plugin_dirs = dir_ptrs_.data();
        info.plugin_dir_count = static_cast<uint32_t>(dir_ptrs_.size());
        info.static_libraries = static_libraries.data();
        info.static_library_count = static_cast<uint32_t>(static_libraries.size());
        info.output_queue_capacity = queue_capacity;
        info.log = log;
        info.log_user = log_user;
        status_ = pn_engine_create(&info, &engine_, &err_);
    }
    ~Engine() { pn_engine_destroy(engine_); }
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    pn_engine_t* get() const { return engine_; }
    pn_status_t status() const { return status_; }
    const pn_error_t& error() const { return err_; }

    nlohmann::json describe() const {
        size_t size = 0;
        if (pn_engine_describe(engine_, nullptr, 0, &size) != PN_E_INVALID_ARGUMENT || size == 0)
            return nullptr;
        std::string text(size, '\0');
        if (pn_engine_describe(engine_, &text[0], size, &size) != PN_OK) return nullptr;
        text.resize(size - 1);
        return nlohmann::json::parse(text);
    }

    std::vector<pn_output_t> poll_all() const {
        std::vector<pn_output_t> out;
        pn_output_t o;
        while (pn_engine_poll(engine_, &o) == PN_OK) out.push_back(o);
        return out;
    }

private:
    std::vector<std::string> dirs_;
    std::vector<const char*> dir_ptrs_;
    pn_engine_t* engine_ = nullptr;
    pn_error_t err_;
    pn_status_t status_ = PN_E_INTERNAL;
};

constexpr int64_t kT0Ns = 1000000000;  // 1 s
constexpr int64_t kDtNs = 10000000;    // 100 Hz

inline int64_t sample_t_ns(size_t k) { return kT0Ns + static_cast<int64_t>(k) * kDtNs; }

// A synthetic walk: gravity plus a 2 Hz vertical bounce and a small yaw rate.
inline pn_imu_t imu_sample(size_t k) {
    pn_imu_t s;
    std::memset(&s, 0, sizeof s);
    s.header.struct_size = sizeof s;
    s.header.type = PN_REC_IMU;
    s.header.t_ns = sample_t_ns(k);
    const double t = static_cast<double>(k) * 0.01;
    s.accel_mps2[0] = 0.3 * std::sin(2 * 3.14159265358979323846 * 2.0 * t);
    s.accel_mps2[2] = 9.81 + 1.5 * std::cos(2 * 3.14159265358979323846 * 2.0 * t);
    s.gyro_radps[2] = 0.01;
    return s;
}

inline std::vector<pn_imu_t> walk(size_t first, size_t count) {
    std::vector<pn_imu_t> v;
    for (size_t k = first; k < first + count; ++k) v.push_back(imu_sample(k));
    return v;
}

inline pn_status_t push(const Engine& e, const std::vector<pn_imu_t>& samples, pn_error_t* err = nullptr) {
    return pn_engine_push_imu(e.get(), samples.data(), samples.size(), sizeof(pn_imu_t), err);
}

inline std::vector<pn_output_t> of_type(const std::vector<pn_output_t>& v, pn_record_type_t type) {
    std::vector<pn_output_t> out;
    for (const auto& o : v)
        if (o.header.type == type) out.push_back(o);
    return out;
}

// The rejected entry of describe whose path ends with `file`, or null.
inline nlohmann::json rejected_entry(const nlohmann::json& d, const std::string& file) {
    for (const auto& r : d.at("rejected")) {
        const std::string p = r.at("path").get<std::string>();
        if (p.size() >= file.size() && p.compare(p.size() - file.size(), file.size(), file) == 0) return r;
    }
    return nullptr;
}

inline bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

}  // namespace pednav::test
