// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the C API push path. The first byte picks the preset
// (configs/foot, chest, waist, handheld.json, plugins linked in); the rest is
// decoded into a sequence of calls on that engine: single records of every
// input type (pn_engine_push), batches (pn_engine_push_imu with a stride,
// pn_engine_push_records), bursts of a synthetic walk, time jumps back and
// forward, poll / poll_many / get_latest, flush, reset, set_start /
// set_attitude / set_origin, the output mask, reconfigure, load_map and
// describe. Every call must answer with a status of its API; crashes, hangs,
// leaks and sanitizer reports are findings.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "byte_reader.hpp"
#include "record_maker.hpp"
#include "static_plugins.hpp"

namespace {

using pednav::fuzz::ByteReader;
using pednav::fuzz::RecordMaker;
using pednav::fuzz::RecordSlot;

const char* const kPresets[] = {"foot", "chest", "waist", "handheld"};
constexpr size_t kPresetCount = sizeof kPresets / sizeof kPresets[0];
constexpr size_t kMaxBatch = 16;

// A one-room local-metre map (docs/maps.md) for the presets with a map matcher.
const char kRoomMap[] =
    R"({"type":"FeatureCollection","pednav:crs":"local-enu","features":[)"
    R"({"type":"Feature","properties":{"pednav:kind":"wall","pednav:floor":0},"geometry":{"type":"LineString",)"
    R"("coordinates":[[-10,-10],[10,-10],[10,10],[-10,10],[-10,-10]]}},)"
    R"({"type":"Feature","properties":{"pednav:kind":"zone","pednav:floor":0},"geometry":{"type":"Polygon",)"
    R"("coordinates":[[[-10,-10],[10,-10],[10,10],[-10,10]]]}}]})";

const std::vector<std::string>& preset_texts() {
    static const std::vector<std::string> texts = [] {
        std::vector<std::string> t;
        for (const char* name : kPresets) {
            std::ifstream in(std::string(PEDNAV_CONFIG_DIR) + "/" + name + ".json", std::ios::binary);
            std::ostringstream s;
            s << in.rdbuf();
            if (!in.good() && s.str().empty()) __builtin_trap();  // the build's presets must be there
            t.push_back(s.str());
        }
        return t;
    }();
    return texts;
}

void check_status(pn_status_t s) {
    if (s > PN_NO_DATA || s < PN_E_BAD_INPUT) __builtin_trap();  // not a status of pn_types.h
}

void drain(pn_engine_t* engine, ByteReader& in) {
    pn_output_t out;
    const unsigned n = in.u8();
    for (unsigned i = 0; i < n; ++i) {
        const pn_status_t s = pn_engine_poll(engine, &out);
        if (s == PN_NO_DATA) return;
        if (s != PN_OK || out.header.struct_size > sizeof out) __builtin_trap();
    }
}

void push_batch(pn_engine_t* engine, ByteReader& in, RecordMaker& maker, pn_error_t* err) {
    RecordSlot slots[kMaxBatch];
    const pn_record_header_t* records[kMaxBatch];
    const size_t n = in.u8() % (kMaxBatch + 1);
    for (size_t i = 0; i < n; ++i) {
        maker.make(PN_REC_IMU + in.u8() % 4, slots[i]);
        records[i] = &slots[i].header;
    }
    const pn_status_t s = pn_engine_push_records(engine, records, n, err);
    check_status(s);
    if (PN_FAILED(s) && (err->detail < 0 || static_cast<size_t>(err->detail) >= n)) __builtin_trap();
}

void push_imu_strided(pn_engine_t* engine, ByteReader& in, RecordMaker& maker, pn_error_t* err) {
    RecordSlot slots[kMaxBatch];
    const size_t n = in.u8() % (kMaxBatch + 1);
    for (size_t i = 0; i < n; ++i) maker.make(PN_REC_IMU, slots[i]);
    // Samples a RecordSlot apart, or read at a shorter stride (inside the same
    // buffer): a sample whose struct_size exceeds the stride must be refused.
    const size_t stride = (in.u8() & 1) != 0 ? sizeof(RecordSlot) : in.u8() * size_t{2};
    check_status(pn_engine_push_imu(engine, &slots[0].imu, n, stride, err));
}

void walk_burst(pn_engine_t* engine, ByteReader& in, RecordMaker& maker, pn_error_t* err) {
    const unsigned n = 1 + in.u8();
    const bool still = (in.u8() & 1) != 0;
    std::vector<pn_imu_t> samples(n);
    for (unsigned i = 0; i < n; ++i) maker.make_walk_imu(i, still, samples[i]);
    check_status(pn_engine_push_imu(engine, samples.data(), n, sizeof(pn_imu_t), err));
}

void before_first_push(pn_engine_t* engine, ByteReader& in, pn_error_t* err) {
    switch (in.u8() % 3) {
        case 0: {
            const double pos[3] = {in.raw_double(), static_cast<double>(in.i16()), 0.0};
            check_status(pn_engine_set_start(engine, pos, static_cast<double>(in.i16()) / 90.0, err));
            break;
        }
        case 1: {
            const double q[4] = {static_cast<double>(in.i16()) / 32768.0, static_cast<double>(in.i16()) / 32768.0,
                                 static_cast<double>(in.i16()) / 32768.0, static_cast<double>(in.i16()) / 32768.0};
            check_status(pn_engine_set_attitude(engine, q, err));
            break;
        }
        default: {
            const pn_geo_point_t origin{static_cast<double>(in.i16()) / 300.0, static_cast<double>(in.i16()) / 150.0,
                                        in.raw_double()};
            check_status(pn_engine_set_origin(engine, &origin, err));
            double enu[3] = {1.0, 2.0, 3.0};
            pn_geo_point_t geo;
            if (pn_engine_geo_from_enu(engine, enu, &geo) == PN_OK) check_status(pn_engine_enu_from_geo(engine, &geo, enu));
            break;
        }
    }
}

void look(pn_engine_t* engine, ByteReader& in) {
    pn_output_t out;
    check_status(pn_engine_get_latest(engine, in.u8() % (PN_REC_TYPE_COUNT + 1), &out));
    (void)pn_engine_latency_ns(engine);
    size_t size = 0;
    if (pn_engine_describe(engine, nullptr, 0, &size) != PN_E_INVALID_ARGUMENT) __builtin_trap();
    std::string text(size, '\0');
    if (pn_engine_describe(engine, text.data(), text.size(), &size) != PN_OK) __builtin_trap();
}

void settings(pn_engine_t* engine, ByteReader& in, pn_error_t* err) {
    switch (in.u8() % 4) {
        case 0: check_status(pn_engine_set_output_mask(engine, in.u64())); break;
        case 1: check_status(pn_engine_load_map(engine, "pednav.map/1", kRoomMap, sizeof kRoomMap - 1, err)); break;
        case 2: {
            const std::string_view bytes = in.bytes(in.u8());
            check_status(pn_engine_load_map(engine, "pednav.map/1", bytes.data(), bytes.size(), err));
            break;
        }
        default: {
            static const char* const roles[] = {"step_detector", "attitude_estimator", "position_filter", "map_matcher",
                                                "foot/position_filter", "nowhere"};
            const std::string params(in.bytes(in.u8()));
            check_status(pn_engine_reconfigure(engine, roles[in.u8() % 6], params.c_str(), params.size(), err));
            break;
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    ByteReader in(data, size);
    const std::string& config = preset_texts()[in.u8() % kPresetCount];
    pn_status_t status = PN_OK;
    pn_engine_t* engine = pednav::fuzz::create_engine(config.c_str(), config.size(), &status);
    if (engine == nullptr) __builtin_trap();  // a preset that does not load
    RecordMaker maker(in);
    pn_error_t err{};
    err.struct_size = sizeof err;
    RecordSlot slot;
    for (unsigned op = 0; !in.done() && op < 256; ++op) {
        switch (in.u8() % 16) {
            case 0: case 1: case 2: case 3: {
                maker.make(PN_REC_IMU + in.u8() % 4, slot);
                check_status(pn_engine_push(engine, &slot.header, &err));
                break;
            }
            case 4: walk_burst(engine, in, maker, &err); break;
            case 5: push_batch(engine, in, maker, &err); break;
            case 6: push_imu_strided(engine, in, maker, &err); break;
            case 7: drain(engine, in); break;
            case 8: {
                pn_output_t out[8];
                size_t count = 0;
                if (pn_engine_poll_many(engine, out, in.u8() % 9, &count) != PN_OK || count > 8) __builtin_trap();
                break;
            }
            case 9: check_status(pn_engine_flush(engine, &err)); break;
            case 10: check_status(pn_engine_reset(engine, &err)); break;
            case 11: before_first_push(engine, in, &err); break;
            case 12: look(engine, in); break;
            case 13: settings(engine, in, &err); break;
            case 14: maker.jump(static_cast<int64_t>(in.i16()) * 1000000); break;
            default: maker.jump(static_cast<int64_t>(in.u32()) * 1000000000LL * ((in.u8() & 1) != 0 ? -1 : 1)); break;
        }
    }
    check_status(pn_engine_flush(engine, &err));
    pn_output_t out;
    while (pn_engine_poll(engine, &out) == PN_OK) {
    }
    pn_engine_destroy(engine);
    return 0;
}
