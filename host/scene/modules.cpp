#include "scene/modules.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <stdexcept>

#include "scene/discovery.hpp"

namespace fgr {

std::filesystem::path module_directory() {
    return (executable_dir() / FGR_MODULES_FROM_BIN).lexically_normal();
}

void* module_entry(const std::string& file_name, const std::string& entry,
                   const std::string& needed_for) {
    const std::filesystem::path path = module_directory() / file_name;
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
