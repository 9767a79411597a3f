// SPDX-License-Identifier: Apache-2.0
// Internal: the table of formats. Each reader says whether a file is its
// format (from the head of the file only) and opens it: reads its head
// (header, preamble, units) into a LogBuilder and returns the RowReader that
// reads the rest a few lines at a time.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "input_file.hpp"
#include "log_builder.hpp"
#include "text_file.hpp"

namespace pednav::io::detail {

// Reads the lines after a file's head into its LogBuilder.
class RowReader {
public:
    virtual ~RowReader() = default;
    // Reads about `lines` more lines; false once the input has ended (its
    // end-of-input issues and notes given).
    virtual bool read_lines(size_t lines) = 0;
    // Record types (PN_REC_MASK bits) it may still produce.
    virtual uint64_t record_types() const = 0;
    // Read whole at the first read_lines: every record comes at once.
    virtual bool whole_file() const { return false; }
    virtual uint64_t bytes_read() const = 0;
    virtual uint64_t bytes_total() const = 0;
};

struct FormatReader {
    const char* name;
    const char* description;
    bool (*detect)(const TextFile& head);
    std::unique_ptr<RowReader> (*open)(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                       SensorLog& log);
};

const std::vector<FormatReader>& format_readers();

// The file to open for `path`: itself, or for a folder holding a two-file
// recording its accelerometer file.
std::string resolve_recording_path(const std::string& path);
// The reader of options.format, or the one detected from the head; throws
// ReadError naming `path` when there is none.
const FormatReader& choose_reader(const std::string& path, const TextFile& head, const ReadOptions& options);

// Index of the first line that is neither blank nor a comment ('#', '%', '//'), or lines.size().
size_t first_content_line(const TextFile& file);
// first_content_line, for a reader that needs a header there: throws ReadError
// naming `format` when the file holds only blank and comment lines.
size_t header_line_index(const TextFile& file, const char* format);

// A format read whole: `read` gets the whole file at the first read_lines.
using WholeFileRead = void (*)(const TextFile& file, const ReadOptions& options, LogBuilder& builder,
                               SensorLog& log);
std::unique_ptr<RowReader> open_whole_file(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                           SensorLog& log, WholeFileRead read);

// Reader entry points, one source file each.
bool detect_pednav_csv(const TextFile& head);
std::unique_ptr<RowReader> open_pednav_csv(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                           SensorLog& log);
bool detect_xio_csv(const TextFile& head);
std::unique_ptr<RowReader> open_xio_csv(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                        SensorLog& log);
bool detect_microstrain_a(const TextFile& head);
bool detect_microstrain_b(const TextFile& head);
std::unique_ptr<RowReader> open_microstrain(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                            SensorLog& log);
bool detect_xsens_mtw_tsv(const TextFile& head);
bool detect_xsens_mtmanager_csv(const TextFile& head);
std::unique_ptr<RowReader> open_xsens(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                      SensorLog& log);
bool detect_biba_converted_csv(const TextFile& head);
std::unique_ptr<RowReader> open_biba_converted_csv(InputFile& input, const ReadOptions& options,
                                                   LogBuilder& builder, SensorLog& log);
bool detect_humolire(const TextFile& head);
std::unique_ptr<RowReader> open_humolire(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                         SensorLog& log);
bool detect_ipin(const TextFile& head);
std::unique_ptr<RowReader> open_ipin(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                     SensorLog& log);
bool detect_column_map(const TextFile& head);
std::unique_ptr<RowReader> open_column_map(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                           SensorLog& log);

// Applies a column map (docs/formats.md) to a delimited file; shared by the
// column-map format and built-in maps of known one-off layouts.
std::unique_ptr<RowReader> open_with_column_map(InputFile& input, const nlohmann::json& map,
                                                LogBuilder& builder, SensorLog& log);

}  // namespace pednav::io::detail
