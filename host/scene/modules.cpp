// SPDX-License-Identifier: Apache-2.0
#include "scene/modules.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <stdexcept>
#include <system_error>

#include "scene/discovery.hpp"

namespace fgr {
namespace {

// What each module is to a user: what it does, the package that installs it and the build option
// that builds it. A headless render node installs the package fgr alone, or builds with the
// options off: either way the command that needs a module says in one line how to get it.
struct ModuleOrigin {
    const char* file_name;
    const char* what;
    const char* package;
    const char* option;
    bool built;  // whether this build of fgr built the module (FGR_BUILT_*, host/scene/CMakeLists)
};
constexpr ModuleOrigin kModuleOrigins[] = {
    {"libfgr_viewer.so", "the viewer", "fgr-viewer", "FGR_BUILD_VIEWER", FGR_BUILT_VIEWER != 0},
    {"libfgr_video_ffmpeg.so", "video encoding", "fgr-video", "FGR_BUILD_VIDEO",
     FGR_BUILT_VIDEO != 0},
    {"libfgr_mpi.so", "MPI support", "fgr-mpi", "FGR_MPI", FGR_BUILT_MPI != 0},
};

// Throws the one-line "not installed" error when `path` is a module of kModuleOrigins that is
// missing; returns otherwise (a module that exists but does not load gets dlopen's reason).
void refuse_missing_module(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::exists(path, error)) return;
    for (const ModuleOrigin& origin : kModuleOrigins) {
        if (path.filename() != origin.file_name) continue;
        if (!origin.built) {
            throw std::runtime_error(fmt::format(
                "{} is not in this fgr: it was built with -D{}=OFF (build with -D{}=ON, or "
                "install the packages fgr and {})",
                origin.what, origin.option, origin.option, origin.package));
        }
        throw std::runtime_error(fmt::format(
            "{} is not installed: {} is missing (install the {} package, or build with -D{}=ON)",
            origin.what, path.string(), origin.package, origin.option));
    }
}

}  // namespace

std::filesystem::path module_directory() {
    return (executable_dir() / FGR_MODULES_FROM_BIN).lexically_normal();
}

void* module_entry(const std::string& file_name, const std::string& entry,
                   const std::string& needed_for) {
    const std::filesystem::path path = module_directory() / file_name;
    refuse_missing_module(path);
    // RTLD_LOCAL: the libraries the module links stay its own. dlopen counts references, so a
    // second call returns the module already loaded.
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) {
        const char* why = dlerror();
        throw std::runtime_error(fmt::format("{} needs fgr's module {}: {}", needed_for, file_name,
                                             why ? why : "cannot load it"));
    }
    void* address = dlsym(module, entry.c_str());
    if (!address) {
        throw std::runtime_error(fmt::format("{} needs fgr's module {}, but {} has no {}",
                                             needed_for, file_name, path.string(), entry));
    }
    spdlog::debug("{}: {} from {}", needed_for, entry, path.string());
    return address;
}

void refuse_module_version(const std::string& file_name, int found, int expected) {
    throw std::runtime_error(fmt::format(
        "{} in {} belongs to another build of fgr (interface version {}, this fgr's is {})",
        file_name, module_directory().string(), found, expected));
}

}  // namespace fgr
