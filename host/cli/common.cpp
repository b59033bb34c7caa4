#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "fgr/atomic_file.hpp"

namespace fgr {
namespace {

std::string scene_ids(const std::vector<Scene>& scenes) {
    std::string ids;
    for (const auto& scene : scenes) ids += (ids.empty() ? "" : ", ") + scene.id;
    return ids.empty() ? "none found" : ids;
}

}  // namespace

Discovery discover() { return discover_scenes(plugin_search_path(executable_dir())); }

const Scene& find_scene(const Discovery& found, const std::string& id) {
    for (const auto& scene : found.scenes) {
        if (scene.id == id) return scene;
    }
    throw UsageError(fmt::format("unknown scene '{}' (available: {})", id, scene_ids(found.scenes)));
}

ComputeDevice open_requested_device(int index) {
    if (index >= static_cast<int>(list_devices().size())) {
        throw UsageError(fmt::format("no OpenCL device {} (see `fgr info`)", index));
    }
    return open_device(index);
}

void add_device_options(CLI::App* command, int& device, int& packet_width) {
    command->add_option("--device", device, "OpenCL device index (see `fgr info`)")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--packet-width", packet_width,
                        "rays per work-item (default: 16 on CPUs, 1 on GPUs)")
        ->check(CLI::IsMember({1, 4, 8, 16}));
}

void add_precision_option(CLI::App* command, Precision& precision, const std::string& auto_means) {
    std::vector<std::string> names;
    for (Precision choice : {Precision::Float, Precision::Double, Precision::Auto}) {
        names.emplace_back(precision_name(choice));
    }
    const auto choose = [&precision](const std::string& name) {
        precision = parse_precision(name);
    };
    command
        ->add_option_function<std::string>("--precision", choose,
                                           "float, double, or auto (default): double " + auto_means)
        ->check(CLI::IsMember(names));
}

void check_output_directory(const std::filesystem::path& file) {
    const auto directory = file.has_parent_path() ? file.parent_path() : ".";
    if (std::error_code error; !std::filesystem::is_directory(directory, error)) {
        throw UsageError(fmt::format("cannot write '{}': directory '{}' does not exist",
                                     file.string(), directory.string()));
    }
}

void write_output(const std::filesystem::path& file, const std::string& text) {
    try {
        write_text_file_atomically(file, text);
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
}

}  // namespace fgr
