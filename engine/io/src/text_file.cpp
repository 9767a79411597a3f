// SPDX-License-Identifier: Apache-2.0
#include "text_file.hpp"

#include <cctype>

#include "line_reader.hpp"
#include "pednav_io/sensor_log.hpp"

namespace pednav::io::detail {

void TextFileBuilder::add(std::string_view line) {
    file_.data.append(line);
    ends_.push_back(file_.data.size());
}

const TextFile& TextFileBuilder::file() {
    file_.lines.resize(ends_.size());
    size_t start = 0;
    for (size_t i = 0; i < ends_.size(); ++i) {
        file_.lines[i] = std::string_view(file_.data).substr(start, ends_[i] - start);
        start = ends_[i];
    }
    return file_;
}

void add_remaining_lines(LineReader& reader, TextFileBuilder& builder) {
    std::string_view line;
    while (reader.next(&line)) builder.add(line);
}

TextFile TextFileBuilder::take() {
    TextFile out;  // returned in place: its views point into its own data
    out.path = file_.path;
    out.data = std::move(file_.data);
    out.lines.resize(ends_.size());
    size_t start = 0;
    for (size_t i = 0; i < ends_.size(); ++i) {
        out.lines[i] = std::string_view(out.data).substr(start, ends_[i] - start);
        start = ends_[i];
    }
    ends_.clear();
    file_.data.clear();
    file_.lines.clear();
    return out;
}

TextFile load_text_file(const std::string& path) {
    LineReader reader(path);
    TextFileBuilder builder(path);
    add_remaining_lines(reader, builder);
    TextFile file = builder.take();
    bool blank = true;
    for (auto line : file.lines) {
        if (!trim(line).empty()) {
            blank = false;
            break;
        }
    }
    if (blank) throw ReadError(path, 0, "the file is empty (only blank lines)");
    return file;
}

char guess_delimiter(std::string_view header) {
    size_t tabs = 0, commas = 0, semis = 0;
    for (char c : header) {
        if (c == '\t') ++tabs;
        if (c == ',') ++commas;
        if (c == ';') ++semis;
    }
    if (tabs >= commas && tabs >= semis && tabs > 0) return '\t';
    if (commas >= semis && commas > 0) return ',';
    if (semis > 0) return ';';
    return ' ';
}

std::string to_lower(std::string_view s) {
    std::string out(s);
    for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool starts_with(std::string_view s, std::string_view prefix) {
    return s.size() >= prefix.size() && s.substr(0, prefix.size()) == prefix;
}

bool ends_with(std::string_view s, std::string_view suffix) {
    return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

}  // namespace pednav::io::detail
