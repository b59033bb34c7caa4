#include "fgr/plugin_loader.hpp"

#include <dlfcn.h>

#include <exception>
#include <string_view>
#include <utility>

#include <spdlog/fmt/fmt.h>

namespace fgr {
namespace {

// --- Loading -------------------------------------------------------------------------------------

// Owns a dlopen handle; dlclose on destruction.
class SharedLibrary {
public:
    explicit SharedLibrary(void* handle) : handle_(handle) {}
    SharedLibrary(SharedLibrary&& other) noexcept
        : handle_(std::exchange(other.handle_, nullptr)) {}
    SharedLibrary& operator=(SharedLibrary&& other) noexcept {
        if (this != &other) {
            close();
            handle_ = std::exchange(other.handle_, nullptr);
        }
        return *this;
    }
    SharedLibrary(const SharedLibrary&) = delete;
    SharedLibrary& operator=(const SharedLibrary&) = delete;
    ~SharedLibrary() { close(); }

    explicit operator bool() const { return handle_ != nullptr; }
    void* symbol(const char* name) const { return dlsym(handle_, name); }

private:
    void close() {
        if (handle_ != nullptr) dlclose(handle_);
        handle_ = nullptr;
    }
    void* handle_;
};

// dlerror()'s message, without the "<file>: " prefix glibc puts in front: callers name the file.
std::string last_dl_error(const std::filesystem::path& file) {
    const char* message = dlerror();
    if (message == nullptr) return "unknown error";
    const std::string_view text = message;
    const std::string prefix = file.string() + ": ";
    return std::string(text.starts_with(prefix) ? text.substr(prefix.size()) : text);
}

LoadResult failure(std::string reason) { return LoadResult{std::nullopt, std::move(reason)}; }

}  // namespace

LoadResult load_scene_plugin(const std::filesystem::path& file) {
    try {
        dlerror();  // clear any stale message so the one we report is ours
        const SharedLibrary library(dlopen(file.c_str(), RTLD_LAZY | RTLD_LOCAL));
        if (!library) return failure("not a loadable shared library: " + last_dl_error(file));
        void* symbol = library.symbol(FGR_SCENE_ENTRY_SYMBOL);
        if (symbol == nullptr) {
            return failure(fmt::format("no entry symbol '{}'", FGR_SCENE_ENTRY_SYMBOL));
        }
        // POSIX guarantees a data pointer from dlsym converts to a function pointer.
        const auto entry = reinterpret_cast<fgr_scene_entry_fn>(symbol);
        const fgr_scene_desc* desc = entry();
        if (desc == nullptr) return failure("entry returned NULL");
        LoadResult result = copy_scene_description(desc);
        if (result.scene) result.scene->plugin_file = file;
        return result;  // `library` closes here, after everything was copied
    } catch (const std::exception& error) {
        return failure(fmt::format("loading failed: {}", error.what()));
    } catch (...) {
        // A C++ plugin's entry could throw despite the C ABI; keep it from reaching the caller.
        return failure("entry threw an exception");
    }
}

}  // namespace fgr
