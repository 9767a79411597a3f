// SPDX-License-Identifier: Apache-2.0
// Internal: the GNSS readers (pednav_io/gnss_log.hpp), one source file each.
#pragma once

#include "log_builder.hpp"
#include "pednav_io/gnss_log.hpp"
#include "text_file.hpp"

namespace pednav::io::detail {

bool detect_gnss_csv(const TextFile& file);
void read_gnss_csv(const TextFile& file, const GnssReadOptions& options, LogBuilder& builder, SensorLog& log);
bool detect_nmea(const TextFile& file);
void read_nmea(const TextFile& file, const GnssReadOptions& options, LogBuilder& builder, SensorLog& log);

}  // namespace pednav::io::detail
