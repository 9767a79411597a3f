// SPDX-License-Identifier: Apache-2.0
#include "text_file.hpp"

#include <sys/stat.h>
#include <cctype>
#include <fstream>
#include <sstream>

#include "pednav_io/sensor_log.hpp"

namespace pednav::io::detail {

TextFile load_text_file(const std::string& path) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) throw ReadError(path, 0, "file not found");
    if (S_ISDIR(st.st_mode)) throw ReadError(path, 0, "is a folder, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ReadError(path, 0, "cannot open the file for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    TextFile file;
    file.path = path;
    file.data = buffer.str();
    if (file.data.empty()) throw ReadError(path, 0, "the file is empty");
    if (file.data.size() >= 2 && ((file.data[0] == '\xff' && file.data[1] == '\xfe') ||
                                  (file.data[0] == '\xfe' && file.data[1] == '\xff'))) {
        throw ReadError(path, 0, "UTF-16 text: save the file as UTF-8 or ASCII");
    }
    if (file.data.compare(0, 3, "\xef\xbb\xbf") == 0) file.data.erase(0, 3);  // UTF-8 byte order mark

    // Binary check on the first 64 KiB: any NUL byte, or more than 5 % control
    // characters other than tab, CR, LF.
    const size_t probe = std::min<size_t>(file.data.size(), 65536);
    size_t control = 0;
    for (size_t i = 0; i < probe; ++i) {
        const auto c = static_cast<unsigned char>(file.data[i]);
        if (c == 0) throw ReadError(path, 0, "binary file (contains NUL bytes), not a text recording");
        if (c < 32 && c != '\t' && c != '\r' && c != '\n') ++control;
    }
    if (control * 20 > probe)
        throw ReadError(path, 0, "binary file (control characters), not a text recording");

    std::string_view all(file.data);
    size_t start = 0;
    while (start < all.size()) {
        size_t end = all.find('\n', start);
        if (end == std::string_view::npos) end = all.size();
        std::string_view line = all.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        file.lines.push_back(line);
        start = end + 1;
    }
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
