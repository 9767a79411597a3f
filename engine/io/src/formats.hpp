// SPDX-License-Identifier: Apache-2.0
// Internal: the table of formats. Each reader says whether a file is its
// format (from the header lines only) and reads it into a LogBuilder.
#pragma once

#include <string>
#include <vector>

#include "log_builder.hpp"
#include "text_file.hpp"

namespace pednav::io::detail {

struct FormatReader {
    const char* name;
    const char* description;
    bool (*detect)(const TextFile& file);
    void (*read)(const TextFile& file, const ReadOptions& options, LogBuilder& builder, SensorLog& log);
};

const std::vector<FormatReader>& format_readers();

// Index of the first line that is neither blank nor a comment ('#', '%', '//'), or lines.size().
size_t first_content_line(const TextFile& file);
// first_content_line, for a reader that needs a header there: throws ReadError
// naming `format` when the file holds only blank and comment lines.
size_t header_line_index(const TextFile& file, const char* format);

// Reader entry points, one source file each.
bool detect_pednav_csv(const TextFile& file);
void read_pednav_csv(const TextFile& file, const ReadOptions& options, LogBuilder& builder, SensorLog& log);
bool detect_xio_csv(const TextFile& file);
void read_xio_csv(const TextFile& file, const ReadOptions& options, LogBuilder& builder, SensorLog& log);
bool detect_microstrain_a(const TextFile& file);
bool detect_microstrain_b(const TextFile& file);
void read_microstrain(const TextFile& file, const ReadOptions& options, LogBuilder& builder, SensorLog& log);
bool detect_xsens_mtw_tsv(const TextFile& file);
bool detect_xsens_mtmanager_csv(const TextFile& file);
void read_xsens(const TextFile& file, const ReadOptions& options, LogBuilder& builder, SensorLog& log);
bool detect_biba_converted_csv(const TextFile& file);
void read_biba_converted_csv(const TextFile& file, const ReadOptions& options, LogBuilder& builder,
                             SensorLog& log);
bool detect_humolire(const TextFile& file);
void read_humolire(const TextFile& file, const ReadOptions& options, LogBuilder& builder, SensorLog& log);
bool detect_ipin(const TextFile& file);
void read_ipin(const TextFile& file, const ReadOptions& options, LogBuilder& builder, SensorLog& log);
bool detect_column_map(const TextFile& file);
void read_column_map(const TextFile& file, const ReadOptions& options, LogBuilder& builder, SensorLog& log);

// Applies a column map (docs/formats.md) to a delimited file; shared by the
// column-map format and built-in maps of known one-off layouts.
void read_with_column_map(const TextFile& file, const nlohmann::json& map, LogBuilder& builder,
                          SensorLog& log);

}  // namespace pednav::io::detail
