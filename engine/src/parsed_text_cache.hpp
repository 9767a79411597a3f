// SPDX-License-Identifier: Apache-2.0
// Texts parsed once per process. Every engine created (a reset, each walk of a
// fleet, each input of a fuzzer) reads the same plugin manifests and parameter
// schemas again, and parsing them costs more than the rest of creating the
// engine. Keyed by the text itself, never by its address: a library unloaded
// and another loaded at the same address must not inherit its entry. A text
// whose parse throws is not kept, so its error is raised every time.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>

namespace pednav::engine {

template <class T>
class ParsedTextCache {
public:
    // The value parse(key) gave the first time this key was asked for.
    // [thread-safe]: engines in several threads share the cache.
    template <class Parse>
    std::shared_ptr<const T> get(std::string key, Parse&& parse) {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            if (const auto it = parsed_.find(key); it != parsed_.end()) return it->second;
        }
        auto value = std::make_shared<const T>(parse(key));  // outside the lock: parsing may be slow or throw
        const std::lock_guard<std::mutex> lock(mutex_);
        return parsed_.emplace(std::move(key), std::move(value)).first->second;
    }

private:
    std::mutex mutex_;
    std::unordered_map<std::string, std::shared_ptr<const T>> parsed_;
};

}  // namespace pednav::engine
