// SPDX-License-Identifier: Apache-2.0
#include "text_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>

#include "pednav_io/sensor_log.hpp"

namespace pednav::io::detail {

namespace {

// Recordings are text; a device (/dev/zero), a pipe or a file that is not text
// must be refused after its first KiB, not after reading all of it.
constexpr size_t kProbeBytes = 1024;
constexpr size_t kWideProbeBytes = 65536;
constexpr size_t kChunkBytes = size_t{1} << 20;
// A pipe or device has no size to read up to; text beyond this is refused.
constexpr size_t kMaxStreamBytes = size_t{1} << 30;

// Throws when data[from, to) shows a binary file: any NUL byte, or more than
// 5 % control characters other than tab, CR, LF.
void check_text(const std::string& path, const std::string& data, size_t to) {
    size_t control = 0;
    for (size_t i = 0; i < to; ++i) {
        const auto c = static_cast<unsigned char>(data[i]);
        if (c == 0) {
            throw ReadError(path, 0,
                            "binary file (a NUL byte at offset " + std::to_string(i) + "), not a text recording");
        }
        if (c < 32 && c != '\t' && c != '\r' && c != '\n') ++control;
    }
    if (control * 20 > to)
        throw ReadError(path, 0, "binary file (control characters), not a text recording");
}

void check_start(const std::string& path, const std::string& data) {
    if (data.size() >= 2 && ((data[0] == '\xff' && data[1] == '\xfe') || (data[0] == '\xfe' && data[1] == '\xff')))
        throw ReadError(path, 0, "UTF-16 text: save the file as UTF-8 or ASCII");
    check_text(path, data, data.size());
}

struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) close(fd);
    }
};

// Reads the whole input into `data`, checking its start before reading on.
void read_checked(const std::string& path, const struct stat& st, std::string& data) {
    Fd in{open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (in.fd < 0) throw ReadError(path, 0, std::string("cannot open the file for reading: ") + std::strerror(errno));
    const bool regular = S_ISREG(st.st_mode);
    if (regular) data.reserve(static_cast<size_t>(st.st_size));
    bool probed = false, wide_probed = false;
    while (true) {
        const size_t want = !probed ? kProbeBytes : kChunkBytes;
        const size_t old_size = data.size();
        data.resize(old_size + want);
        const ssize_t got = read(in.fd, &data[old_size], want);
        if (got < 0) {
            if (errno == EINTR) {
                data.resize(old_size);
                continue;
            }
            throw ReadError(path, 0, std::string("cannot read the file: ") + std::strerror(errno));
        }
        data.resize(old_size + static_cast<size_t>(got));
        if (!probed || got == 0) {
            probed = true;
            check_start(path, data);
        }
        if (!wide_probed && data.size() >= kWideProbeBytes) {
            wide_probed = true;
            check_text(path, data, kWideProbeBytes);
        }
        if (got == 0) break;
        if (!regular && data.size() > kMaxStreamBytes) {
            throw ReadError(path, 0, "more than " + std::to_string(kMaxStreamBytes >> 20) +
                                         " MiB from a pipe or device without an end: write it to a file first");
        }
    }
    if (!wide_probed) check_text(path, data, data.size());
}

}  // namespace

TextFile load_text_file(const std::string& path) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) throw ReadError(path, 0, "file not found");
    if (S_ISDIR(st.st_mode)) throw ReadError(path, 0, "is a folder, not a file");
    TextFile file;
    file.path = path;
    read_checked(path, st, file.data);
    if (file.data.empty()) throw ReadError(path, 0, "the file is empty");
    if (file.data.compare(0, 3, "\xef\xbb\xbf") == 0) file.data.erase(0, 3);  // UTF-8 byte order mark

    // Lines end at LF, CR LF or a lone CR (classic Mac OS exports).
    std::string_view all(file.data);
    size_t start = 0;
    while (start < all.size()) {
        size_t end = all.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = all.size();
        file.lines.push_back(all.substr(start, end - start));
        start = end + 1;
        if (end + 1 < all.size() && all[end] == '\r' && all[end + 1] == '\n') ++start;
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
