// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <string>
#include <vector>
// pednav demo [--out DIR] [--route NAME] [--seed N] [--rate HZ]: the main job on
// its built-in default. Simulates a walk with a foot-mounted IMU (sensor errors
// on), runs it through the foot preset via the real loader, prints the error
// against the exact truth, writes the track, the truth and an SVG plot.
int pednav_cmd_demo(const std::vector<std::string>& args);
// Its usage text (pednav demo --help).
extern const char* const pednav_cmd_demo_usage;
