// SPDX-License-Identifier: Apache-2.0
// Internal: a sequence of plain values as long as the file it comes from,
// appended and read back in order, in bounded memory: the newest block in
// memory, the older blocks in an unnamed temporary file ($TMPDIR, else /tmp;
// gone when closed). When no temporary file can be made it stays in memory.
// The reader's whole-file summaries (median intervals, gaps, unit checks) read
// their samples back from here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace pednav::io::detail {

// Bytes appended to an unnamed temporary file and read back by offset.
class SpillFile {
public:
    SpillFile() = default;
    ~SpillFile();
    SpillFile(const SpillFile&) = delete;
    SpillFile& operator=(const SpillFile&) = delete;

    // False when no temporary file could be made or written: the caller keeps the bytes.
    bool append(const void* data, size_t bytes);
    void read(uint64_t offset, void* data, size_t bytes) const;  // throws std::runtime_error

private:
    int fd_ = -1;
    bool failed_ = false;
    uint64_t size_ = 0;
};

template <typename T>
class SpillVector {
    static_assert(std::is_trivially_copyable<T>::value, "spilled as bytes");

public:
    explicit SpillVector(size_t block_values = 8192) : block_values_(block_values) {}

    void push_back(const T& v) {
        if (size_ == 0) first_ = v;
        ++size_;
        block_.push_back(v);
        if (block_.size() == block_values_) spill();
    }
    size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const T& front() const { return first_; }
    const T& back() const {
        return block_.empty() ? (kept_.empty() ? last_spilled_ : kept_.back()) : block_.back();
    }

    // f(const T&) for every value, in the order appended.
    template <typename F>
    void for_each(F&& f) const {
        std::vector<T> chunk(spilled_ > 0 ? block_values_ : 0);
        for (size_t at = 0; at < spilled_; at += chunk.size()) {
            const size_t n = spilled_ - at < chunk.size() ? spilled_ - at : chunk.size();
            file_.read(static_cast<uint64_t>(at) * sizeof(T), chunk.data(), n * sizeof(T));
            for (size_t i = 0; i < n; ++i) f(chunk[i]);
        }
        for (const T& v : kept_) f(v);
        for (const T& v : block_) f(v);
    }

private:
    void spill() {
        last_spilled_ = block_.back();
        if (kept_.empty() && file_.append(block_.data(), block_.size() * sizeof(T))) {
            spilled_ += block_.size();
        } else {
            kept_.insert(kept_.end(), block_.begin(), block_.end());
        }
        block_.clear();
    }

    size_t block_values_;
    size_t size_ = 0;
    size_t spilled_ = 0;    // values in file_
    std::vector<T> kept_;   // values after them held in memory (the file could not be written)
    std::vector<T> block_;  // the newest values
    T first_{};
    T last_spilled_{};
    SpillFile file_;
};

}  // namespace pednav::io::detail
