// SPDX-License-Identifier: Apache-2.0
// Tracks written by pednav_io (pednav run --output) read back by the evaluation.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <pednav_eval/track.hpp>
#include <pednav_io/writers.hpp>

#include "test_dir.hpp"

using namespace pednav::eval;

namespace {

std::string temp_path(const char* name) {
    return pednav::eval_test::test_dir() + "/" + name;
}

// 10 s east at 1 m/s, 10 Hz, heading 90 deg, floor known after the first 3 samples.
std::vector<pn_position_t> make_positions() {
    std::vector<pn_position_t> out;
    for (int i = 0; i <= 100; ++i) {
        pn_position_t p{};
        p.header.struct_size = sizeof p;
        p.header.type = PN_REC_POSITION;
        p.header.t_ns = static_cast<int64_t>(i) * 100000000;
        p.pos_enu_m[0] = 0.1 * i;
        p.pos_enu_m[1] = -0.02 * i;
        p.pos_enu_m[2] = i < 50 ? 0.0 : 3.0;
        p.heading_rad = M_PI / 2;
        p.floor = i < 50 ? 0 : 1;
        p.header.flags = i < 3 ? 0u : PN_POSITION_FLAG_HAS_FLOOR;
        out.push_back(p);
    }
    return out;
}

}  // namespace

TEST_CASE("track CSV: read_track_csv reads back what write_track_csv wrote") {
    const std::string path = temp_path("pednav_eval_test_track.csv");
    const auto positions = make_positions();
    pednav::io::write_track_csv(path, positions);
    const Track read = read_track_csv(path);
    const Track direct = track_from_positions(positions);
    REQUIRE(read.samples.size() == positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        CAPTURE(i);
        const TrackSample &a = read.samples[i], &b = direct.samples[i];
        CHECK(a.t_s == doctest::Approx(b.t_s).epsilon(1e-12));
        for (int k = 0; k < 3; ++k) CHECK(std::fabs(a.pos_m[k] - b.pos_m[k]) < 1e-6);
        CHECK(a.heading_deg == doctest::Approx(90.0));
        CHECK(a.has_floor == b.has_floor);
        if (a.has_floor) CHECK(a.floor == b.floor);
    }
    CHECK(read.length_m() == doctest::Approx(direct.length_m()).epsilon(1e-9));
    std::remove(path.c_str());
}

TEST_CASE("track CSV: a row with nan, a hexadecimal number or trailing text is rejected, naming line and column") {
    const std::string path = temp_path("pednav_eval_test_bad_track.csv");
    struct Bad {
        const char* row;
        const char* message;
    } cases[] = {{"0.1,nan,0,0", ":3: non-finite value 'nan' in column x"},
                 {"0.1,0,0x10,0", ":3: not a number: '0x10' in column y"},
                 {"0.1,0,0,1m", ":3: not a number: '1m' in column z"},
                 {",0,0,0", ":3: empty value in column t"}};
    for (const Bad& bad : cases) {
        CAPTURE(bad.row);
        {
            std::ofstream f(path);
            f << "t,x,y,z\n0.0,0,0,0\n" << bad.row << "\n";
        }
        std::string message;
        try {
            read_track_csv(path);
        } catch (const std::runtime_error& e) {
            message = e.what();
        }
        CHECK(message == path + bad.message);
    }
    std::remove(path.c_str());
}
