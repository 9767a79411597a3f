// SPDX-License-Identifier: Apache-2.0
// pn_engine_push_records and pn_engine_poll_many (the batch calls of the
// bindings), and the readers' C API (pn_io.h) on a file written here.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <pednav/pn_io.h>

#include "test_support.hpp"

using namespace pednav::test;

namespace {

std::string steps_config() {
    return make_config({{"step_detector", "org.pednav.test.counting_steps", {}},
                        {"position_filter", "org.pednav.test.step_counter", {}}});
}

bool same_bytes(const std::vector<pn_output_t>& a, const std::vector<pn_output_t>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::memcmp(&a[i], &b[i], a[i].header.struct_size) != 0) return false;
    return true;
}

std::vector<pn_output_t> poll_many_all(const Engine& e, size_t capacity) {
    std::vector<pn_output_t> out, slots(capacity);
    size_t n = 0;
    do {
        REQUIRE(pn_engine_poll_many(e.get(), slots.data(), capacity, &n) == PN_OK);
        out.insert(out.end(), slots.begin(), slots.begin() + static_cast<std::ptrdiff_t>(n));
    } while (n == capacity);
    return out;
}

}  // namespace

TEST_CASE("push_records and poll_many give what push and poll give") {
    const std::vector<pn_imu_t> samples = walk(0, 300);
    Engine one(steps_config(), {fixture_dir("good")});
    REQUIRE(one.status() == PN_OK);
    for (const auto& s : samples) REQUIRE(pn_engine_push(one.get(), &s.header, nullptr) == PN_OK);
    REQUIRE(pn_engine_flush(one.get(), nullptr) == PN_OK);
    const std::vector<pn_output_t> expected = one.poll_all();
    REQUIRE(expected.size() > 20);

    Engine batch(steps_config(), {fixture_dir("good")});
    std::vector<const pn_record_header_t*> pointers;
    for (const auto& s : samples) pointers.push_back(&s.header);
    REQUIRE(pn_engine_push_records(batch.get(), pointers.data(), pointers.size(), nullptr) == PN_OK);
    REQUIRE(pn_engine_flush(batch.get(), nullptr) == PN_OK);
    CHECK(same_bytes(poll_many_all(batch, 7), expected));
    size_t n = 99;
    CHECK(pn_engine_poll_many(batch.get(), nullptr, 0, &n) == PN_OK);
    CHECK(n == 0);
    CHECK(pn_engine_poll_many(nullptr, nullptr, 0, &n) == PN_E_INVALID_ARGUMENT);
}

TEST_CASE("push_records stops at the first refused record, naming its index") {
    std::vector<pn_imu_t> samples = walk(0, 50);
    samples[20].header.t_ns = samples[19].header.t_ns;  // not after the previous one
    Engine e(steps_config(), {fixture_dir("good")});
    std::vector<const pn_record_header_t*> pointers;
    for (const auto& s : samples) pointers.push_back(&s.header);
    pn_error_t err = make_error();
    CHECK(pn_engine_push_records(e.get(), pointers.data(), pointers.size(), &err) == PN_E_OUT_OF_ORDER);
    CHECK(err.detail == 20);
    // The records before it were taken: continuing after it succeeds.
    CHECK(pn_engine_push_records(e.get(), pointers.data() + 21, pointers.size() - 21, &err) == PN_OK);
    CHECK(e.describe()["counters"]["records_in"].get<int>() == 49);
    CHECK(pn_engine_push_records(e.get(), nullptr, 3, &err) == PN_E_INVALID_ARGUMENT);
}

TEST_CASE("pn_io: a recording's streams, merged order, description and errors") {
    std::filesystem::create_directories(PEDNAV_TEST_WORK_DIR);
    const std::string path = std::string(PEDNAV_TEST_WORK_DIR) + "/pn_io_walk.csv";
    {
        std::ofstream f(path);
        f << "t,ax,ay,az,gx,gy,gz,mx,my,mz\n";
        for (int i = 0; i < 100; ++i)
            f << i * 0.01 << ",0.1,0.2,9.8,0.01,0.02,0.03,20,0,-40\n";
        f << "1.00,0.1,0.2,nope,0,0,0,20,0,-40\n";  // a bad row, read past
    }
    pn_recording_t* rec = nullptr;
    pn_error_t err = make_error();
    REQUIRE(pn_recording_open(path.c_str(), "auto", nullptr, &rec, &err) == PN_OK);
    const void* records = nullptr;
    size_t count = 0, stride = 0;
    REQUIRE(pn_recording_stream(rec, PN_REC_IMU, &records, &count, &stride) == PN_OK);
    CHECK(count == 100);
    CHECK(stride == sizeof(pn_imu_t));
    const auto* imu = static_cast<const pn_imu_t*>(records);
    CHECK(imu[1].header.t_ns == 10000000);
    CHECK(imu[1].accel_mps2[2] == doctest::Approx(9.8));
    REQUIRE(pn_recording_stream(rec, PN_REC_MAG, &records, &count, &stride) == PN_OK);
    CHECK(count == 100);
    CHECK(pn_recording_stream(rec, PN_REC_POSITION, &records, &count, &stride) == PN_E_INVALID_ARGUMENT);
    const pn_record_header_t* const* merged = nullptr;
    REQUIRE(pn_recording_merged(rec, &merged, &count) == PN_OK);
    REQUIRE(count == 200);
    CHECK(merged[0]->type == PN_REC_IMU);  // at equal times IMU first, then MAG
    CHECK(merged[1]->type == PN_REC_MAG);
    CHECK(merged[1]->t_ns == merged[0]->t_ns);
    size_t size = 0;
    CHECK(pn_recording_describe(rec, nullptr, 0, &size) == PN_E_INVALID_ARGUMENT);
    std::string text(size, '\0');
    REQUIRE(pn_recording_describe(rec, &text[0], size, &size) == PN_OK);
    const auto d = nlohmann::json::parse(text.c_str());
    CHECK(d["format"] == "pednav-csv");
    CHECK(d["issues"].size() == 1);
    CHECK(d["issues"][0]["line"] == 102);
    CHECK_FALSE(d["notes"].empty());
    pn_recording_destroy(rec);

    CHECK(pn_recording_open((path + ".missing").c_str(), "auto", nullptr, &rec, &err) == PN_E_BAD_INPUT);
    CHECK(rec == nullptr);
    CHECK(std::string(err.where) == path + ".missing");
    CHECK(pn_recording_open(path.c_str(), "auto", "{\"gap\": 1}", &rec, &err) == PN_E_INVALID_ARGUMENT);
    CHECK(std::string(err.where) == "/gap");
    const std::string binary = std::string(PEDNAV_TEST_WORK_DIR) + "/pn_io_binary.csv";
    {
        std::ofstream f(binary, std::ios::binary);
        f << "t,ax\n" << std::string("\0\1\2\3", 4) << "\n";
    }
    CHECK(pn_recording_open(binary.c_str(), "auto", nullptr, &rec, &err) == PN_E_BAD_INPUT);
    CHECK(std::string(err.where).rfind(binary, 0) == 0);
    CHECK(std::string(err.message).size() > 5);
}
