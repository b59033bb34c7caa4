// SPDX-License-Identifier: Apache-2.0
#include "scene/plugin_loader.hpp"

#include <dlfcn.h>
#include <spdlog/fmt/fmt.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include "util/errors.hpp"
#include "util/files.hpp"

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

// A copy of a file under a unique name in the temporary directory, removed on destruction.
class TemporaryCopy {
public:
    // Throws std::runtime_error when the copy cannot be made.
    explicit TemporaryCopy(const std::filesystem::path& original) {
        std::string bytes;
        if (!read_file_bytes(original, bytes).empty()) {
            throw std::runtime_error("cannot read the plugin file");
        }
        std::string pattern =
            (std::filesystem::temp_directory_path() / "fgr-plugin-XXXXXX.so").string();
        const int descriptor = ::mkstemps(pattern.data(), 3);
        if (descriptor < 0) {
            throw std::runtime_error("cannot create a temporary copy: " + errno_message(errno));
        }
        path_ = pattern;
        const bool written = write_all(descriptor, bytes);
        const std::string reason = errno_message(errno);
        ::close(descriptor);
        if (!written) {
            remove();
            throw std::runtime_error("cannot write a temporary copy: " + reason);
        }
    }
    TemporaryCopy(const TemporaryCopy&) = delete;
    TemporaryCopy& operator=(const TemporaryCopy&) = delete;
    ~TemporaryCopy() { remove(); }
    const std::filesystem::path& path() const { return path_; }

private:
    void remove() {
        std::error_code ignored;
        if (!path_.empty()) std::filesystem::remove(path_, ignored);
    }
    static bool write_all(int descriptor, const std::string& bytes) {
        for (std::size_t done = 0; done < bytes.size();) {
            const ssize_t wrote = ::write(descriptor, bytes.data() + done, bytes.size() - done);
            if (wrote < 0 && errno == EINTR) continue;
            if (wrote <= 0) return false;
            done += static_cast<std::size_t>(wrote);
        }
        return true;
    }
    std::filesystem::path path_;
};

// dlopen `image` (the plugin file itself or a copy of it), call its entry, validate and copy;
// messages and the scene's plugin_file name `file`.
LoadResult load_image(const std::filesystem::path& file, const std::filesystem::path& image) {
    try {
        dlerror();  // clear any stale message so the one we report is ours
        const SharedLibrary library(dlopen(image.c_str(), RTLD_LAZY | RTLD_LOCAL));
        if (!library) return failure("not a loadable shared library: " + last_dl_error(image));
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

}  // namespace

LoadResult load_scene_plugin(const std::filesystem::path& file) { return load_image(file, file); }

LoadResult reload_scene_plugin(const std::filesystem::path& file) {
    try {
        const TemporaryCopy copy(file);
        return load_image(file, copy.path());
    } catch (const std::exception& error) {
        return failure(error.what());
    }
}

}  // namespace fgr
