// SPDX-License-Identifier: Apache-2.0
// pn_io.h implemented over the readers of pednav_io. No exception leaves this file.
#include <algorithm>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav/pn_io.h>
#include <pednav_io/sensor_log.hpp>
#include <pednav_io/writers.hpp>

struct pn_recording_t {
    pednav::io::SensorLog log;
    std::vector<const pn_record_header_t*> merged;
    std::vector<pn_truth_point_t> truth;
};

namespace {

void copy_text(char* out, size_t capacity, const std::string& text) {
    const size_t n = std::min(text.size(), capacity - 1);
    std::memcpy(out, text.data(), n);
    out[n] = '\0';
}

void fill_error(pn_error_t* err, pn_status_t code, const std::string& where, const std::string& message,
                int32_t detail = 0) {
    if (!err || err->struct_size < sizeof(pn_error_t)) return;
    err->code = code;
    err->detail = detail;
    copy_text(err->where, sizeof err->where, where);
    copy_text(err->message, sizeof err->message, message);
}

pn_status_t write_text(const std::string& text, char* buffer, size_t capacity, size_t* size) {
    if (size) *size = text.size() + 1;
    if (!buffer || capacity < text.size() + 1) return PN_E_INVALID_ARGUMENT;
    std::memcpy(buffer, text.c_str(), text.size() + 1);
    return PN_OK;
}

// The reader options of options_json; throws std::invalid_argument naming the key at fault.
pednav::io::ReadOptions read_options(const char* format, const char* options_json, nlohmann::json& column_map) {
    pednav::io::ReadOptions ro;
    ro.format = format && *format ? format : "auto";
    if (!options_json || !*options_json) return ro;
    const nlohmann::json doc = nlohmann::json::parse(options_json, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) throw std::invalid_argument("/|options are not a JSON object");
    for (const auto& [key, value] : doc.items()) {
        if (key == "column_map") {
            if (!value.is_object()) throw std::invalid_argument("/column_map|the column map must be an object");
            column_map = value;
            ro.column_map = &column_map;
            if (ro.format == "auto") ro.format = "column-map";
        } else if (key == "gap_s") {
            if (!value.is_number() || !(value.get<double>() > 0.0))
                throw std::invalid_argument("/gap_s|gap_s must be a number > 0 (seconds)");
            ro.gap_s = value.get<double>();
        } else if (key == "max_issues") {
            if (!value.is_number_unsigned()) throw std::invalid_argument("/max_issues|max_issues must be a count");
            ro.max_issues = value.get<size_t>();
        } else {
            throw std::invalid_argument("/" + key + "|unknown option " + key +
                                        " (expected column_map, gap_s, max_issues)");
        }
    }
    return ro;
}

}  // namespace

extern "C" {

pn_status_t pn_recording_open(const char* path, const char* format, const char* options_json,
                              pn_recording_t** recording, pn_error_t* err) {
    if (!recording || !path) {
        fill_error(err, PN_E_INVALID_ARGUMENT, "recording", "path or recording out-pointer is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    *recording = nullptr;
    try {
        nlohmann::json column_map;
        const pednav::io::ReadOptions ro = read_options(format, options_json, column_map);
        auto r = std::make_unique<pn_recording_t>();
        r->log = pednav::io::read_sensor_file(path, ro);
        r->merged = pednav::io::merged_records(r->log);
        for (const auto& p : r->log.truth)
            r->truth.push_back({p.t_s, {p.x_m, p.y_m, p.z_m}, p.floor, p.has_z ? 1 : 0});
        *recording = r.release();
        return PN_OK;
    } catch (const pednav::io::ReadError& e) {
        std::string where = e.path();
        if (e.line() > 0) where += ":" + std::to_string(e.line());
        fill_error(err, PN_E_BAD_INPUT, where, e.reason(), static_cast<int32_t>(e.line()));
        return PN_E_BAD_INPUT;
    } catch (const std::invalid_argument& e) {
        const std::string text = e.what();
        const size_t bar = text.find('|');
        fill_error(err, PN_E_INVALID_ARGUMENT, text.substr(0, bar), text.substr(bar + 1));
        return PN_E_INVALID_ARGUMENT;
    } catch (const std::bad_alloc&) {
        fill_error(err, PN_E_OUT_OF_MEMORY, path, "out of memory");
        return PN_E_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        fill_error(err, PN_E_INTERNAL, path, e.what());
        return PN_E_INTERNAL;
    }
}

void pn_recording_destroy(pn_recording_t* recording) { delete recording; }

pn_status_t pn_recording_stream(const pn_recording_t* recording, pn_record_type_t type, const void** records,
                                size_t* count, size_t* stride_bytes) {
    if (!recording || !records || !count || !stride_bytes) return PN_E_INVALID_ARGUMENT;
    const auto& log = recording->log;
    auto give = [&](const auto& v) {
        *records = v.empty() ? nullptr : v.data();
        *count = v.size();
        *stride_bytes = v.empty() ? 0 : sizeof v.front();
        return PN_OK;
    };
    switch (type) {
        case PN_REC_IMU: return give(log.imu);
        case PN_REC_MAG: return give(log.mag);
        case PN_REC_BARO: return give(log.baro);
        case PN_REC_GNSS: return give(log.gnss);
        default: return PN_E_INVALID_ARGUMENT;
    }
}

pn_status_t pn_recording_merged(const pn_recording_t* recording, const pn_record_header_t* const** records,
                                size_t* count) {
    if (!recording || !records || !count) return PN_E_INVALID_ARGUMENT;
    *records = recording->merged.empty() ? nullptr : recording->merged.data();
    *count = recording->merged.size();
    return PN_OK;
}

pn_status_t pn_recording_truth(const pn_recording_t* recording, const pn_truth_point_t** points, size_t* count) {
    if (!recording || !points || !count) return PN_E_INVALID_ARGUMENT;
    *points = recording->truth.empty() ? nullptr : recording->truth.data();
    *count = recording->truth.size();
    return PN_OK;
}

pn_status_t pn_recording_describe(const pn_recording_t* recording, char* buffer, size_t capacity, size_t* size) {
    if (!recording) return PN_E_INVALID_ARGUMENT;
    try {
        nlohmann::json j = pednav::io::sensor_log_json(recording->log);
        nlohmann::json labels = nlohmann::json::array();
        for (const auto& p : recording->log.truth) labels.push_back(p.label);
        j["truth_labels"] = labels;
        return write_text(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), buffer, capacity, size);
    } catch (const std::exception&) {
        return PN_E_INTERNAL;
    }
}

pn_status_t pn_recording_formats(char* buffer, size_t capacity, size_t* size) {
    try {
        return write_text(nlohmann::json(pednav::io::supported_formats()).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), buffer, capacity, size);
    } catch (const std::exception&) {
        return PN_E_INTERNAL;
    }
}

pn_status_t pn_write_track_csv(const char* path, const pn_position_t* positions, size_t count, pn_error_t* err) {
    if (!path || (count && !positions)) {
        fill_error(err, PN_E_INVALID_ARGUMENT, "write_track_csv", "path or positions is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    try {
        pednav::io::write_track_csv(path, std::vector<pn_position_t>(positions, positions + count));
        return PN_OK;
    } catch (const std::exception& e) {
        fill_error(err, PN_E_IO, path, e.what());
        return PN_E_IO;
    }
}

pn_status_t pn_write_steps_csv(const char* path, const pn_stride_t* strides, size_t count, pn_error_t* err) {
    if (!path || (count && !strides)) {
        fill_error(err, PN_E_INVALID_ARGUMENT, "write_steps_csv", "path or strides is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    try {
        pednav::io::write_steps_csv(path, std::vector<pn_stride_t>(strides, strides + count));
        return PN_OK;
    } catch (const std::exception& e) {
        fill_error(err, PN_E_IO, path, e.what());
        return PN_E_IO;
    }
}

}  // extern "C"
