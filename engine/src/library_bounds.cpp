// SPDX-License-Identifier: Apache-2.0
#include "library_bounds.hpp"

#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dlfcn.h>
#include <link.h>

#include <string_view>

namespace pednav::engine {

namespace {

struct Search {
    ElfW(Addr) base;
    const char* name;
    std::vector<std::pair<uintptr_t, uintptr_t>>* segments;
};

int collect(dl_phdr_info* info, size_t, void* data) {
    auto* search = static_cast<Search*>(data);
    if (info->dlpi_addr != search->base || !info->dlpi_name || std::string_view(info->dlpi_name) != search->name)
        return 0;
    for (ElfW(Half) i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info->dlpi_phdr[i];
        if (ph.p_type != PT_LOAD || !(ph.p_flags & PF_R)) continue;
        const uintptr_t begin = info->dlpi_addr + ph.p_vaddr;
        search->segments->emplace_back(begin, begin + ph.p_memsz);
    }
    return 1;
}

}  // namespace

LibraryBounds::LibraryBounds(void* handle) {
    link_map* map = nullptr;
    if (!handle || dlinfo(handle, RTLD_DI_LINKMAP, &map) != 0 || !map || !map->l_name) return;
    Search search{map->l_addr, map->l_name, &segments_};
    dl_iterate_phdr(&collect, &search);
}

bool LibraryBounds::holds(const void* p, size_t bytes) const {
    const auto a = reinterpret_cast<uintptr_t>(p);
    for (const auto& [begin, end] : segments_)
        if (a >= begin && a <= end && bytes <= end - a) return true;
    return false;
}

bool LibraryBounds::holds_string(const char* s) const {
    const auto a = reinterpret_cast<uintptr_t>(s);
    for (const auto& [begin, end] : segments_) {
        if (a < begin || a >= end) continue;
        for (uintptr_t c = a; c < end; ++c)
            if (*reinterpret_cast<const char*>(c) == '\0') return true;
        return false;
    }
    return false;
}

}  // namespace pednav::engine
