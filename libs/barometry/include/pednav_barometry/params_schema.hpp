// SPDX-License-Identifier: Apache-2.0
// The parameters barometric_altimeter_config() reads (prefix "baro_") as
// JSON Schema members, for a plugin's params schema: one text, units and
// ranges for every plugin that holds an altimeter, each with its own
// defaults. The members come without a trailing comma:
//
//   static constexpr const char* kParamsSchema = R"json({"type": "object",
//     "properties": {
//       "gain": {...},)json" PEDNAV_BAROMETER_PARAMS_SCHEMA(5, 0.3, 1.0, 3.5, 0.1, 5) R"json(
//     }})json";
//
// The ranges are those the altimeter accepts (BarometricAltimeter's
// constructor also checks hysteresis < floor height / 2).
#pragma once

#define PEDNAV_BAROMETER_PARAMS_SCHEMA(reference_s, smoothing_s, rate_smoothing_s, floor_height_m,             \
                                       floor_hysteresis_m, max_gap_s)                                          \
    "\n    \"baro_reference_s\": {\"type\": \"number\", \"x-unit\": \"s\", \"minimum\": 0.01, \"maximum\": 600, " \
    "\"default\": " #reference_s ",\n      \"description\": \"barometer: the reference pressure (altitude 0, "      \
    "floor 0) is the mean over the first this long of readings\"},"                                                \
    "\n    \"baro_smoothing_s\": {\"type\": \"number\", \"x-unit\": \"s\", \"minimum\": 0, \"maximum\": 60, "      \
    "\"default\": " #smoothing_s ",\n      \"description\": \"barometer: time constant of the altitude "            \
    "low-pass; 0 = none\"},"                                                                                         \
    "\n    \"baro_rate_smoothing_s\": {\"type\": \"number\", \"x-unit\": \"s\", \"minimum\": 0.01, \"maximum\": "  \
    "60, \"default\": " #rate_smoothing_s ",\n      \"description\": \"barometer: time constant of the vertical "   \
    "rate's low-pass\"},"                                                                                            \
    "\n    \"baro_floor_height_m\": {\"type\": \"number\", \"x-unit\": \"m\", \"minimum\": 0.5, \"maximum\": 50, " \
    "\"default\": " #floor_height_m ",\n      \"description\": \"barometer: height of one floor (a map's "          \
    "pednav:floor_height_m replaces it in a map matcher)\"},"                                                       \
    "\n    \"baro_floor_hysteresis_m\": {\"type\": \"number\", \"x-unit\": \"m\", \"minimum\": 0, \"maximum\": "   \
    "10, \"default\": " #floor_hysteresis_m ",\n      \"description\": \"barometer: the floor changes this far "    \
    "past half a floor (less than half a floor)\"},"                                                                \
    "\n    \"baro_max_gap_s\": {\"type\": \"number\", \"x-unit\": \"s\", \"minimum\": 0.01, \"maximum\": 3600, "   \
    "\"default\": " #max_gap_s ",\n      \"description\": \"barometer: a longer gap between readings restarts "      \
    "its filters\"}"
