// SPDX-License-Identifier: Apache-2.0
// pednav-manifest LIBRARY [--output FILE]
//
// Opens a just-built plugin library with the engine's own loader, checks its
// library struct and descriptors as the engine would, and writes its manifest
// (docs/loading.md), by default beside the library: libpnp_x.so ->
// libpnp_x.json. pednav_add_plugin() runs it after every link, so a library
// the engine would refuse fails the build with the engine's reason.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "loader.hpp"
#include "manifest.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav-manifest LIBRARY [--output FILE]\n"
    "  writes the plugin manifest of LIBRARY (default: beside it, .so replaced by .json)\n";

std::string base_name(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

int run(int argc, char** argv) {
    std::string library, output;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (a == "--output" && i + 1 < argc) {
            output = argv[++i];
        } else if (!a.empty() && a[0] != '-' && library.empty()) {
            library = a;
        } else {
            std::fprintf(stderr, "pednav-manifest: unexpected argument %s\n%s", a.c_str(), kUsage);
            return 2;
        }
    }
    if (library.empty()) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    if (output.empty()) output = pednav::engine::manifest_path_for(library);

    pednav::engine::Loader loader;
    const bool accepted = loader.open_file(library);
    if (!accepted || !loader.rejected().empty()) {
        for (const auto& r : loader.rejected())
            std::fprintf(stderr, "pednav-manifest: %s: %s\n", r.path.c_str(), r.reason.c_str());
        return 1;
    }
    const std::string text =
        pednav::engine::manifest_json(loader.libraries().front().library, base_name(library)).dump(2) + "\n";
    // What the loader will read back must be exactly what it accepts.
    pednav::engine::parse_manifest(text, output);
    const std::string tmp = output + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out.flush()) {
            std::fprintf(stderr, "pednav-manifest: cannot write %s: %s\n", tmp.c_str(), std::strerror(errno));
            return 1;
        }
    }
    if (std::rename(tmp.c_str(), output.c_str()) != 0) {
        std::fprintf(stderr, "pednav-manifest: cannot write %s: %s\n", output.c_str(), std::strerror(errno));
        std::remove(tmp.c_str());
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const pednav::engine::ManifestError& e) {
        std::fprintf(stderr, "pednav-manifest: %s\n", e.message.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav-manifest: %s\n", e.what());
    }
    return 1;
}
