// fgr info: the OpenCL devices, numbered for --device.
#include <fmt/format.h>

#include "commands.hpp"
#include "fgr/opencl_device.hpp"

namespace fgr {

int command_info() {
    const auto devices = list_devices();
    if (devices.empty()) {
        throw RuntimeFailure("no OpenCL device found (install an OpenCL driver, e.g. pocl-opencl-icd)");
    }
    for (const auto& device : devices) {
        fmt::print("device {}: {}\n", device.index, device.name);
        fmt::print("  platform:       {}\n", device.platform);
        fmt::print("  type:           {}\n", device.is_gpu ? "GPU" : device.is_cpu ? "CPU" : "other");
        fmt::print("  version:        {} (driver {}, {})\n", device.version, device.driver_version,
                   device.opencl_c_version);
        fmt::print("  compute units:  {}\n", device.compute_units);
        fmt::print("  global memory:  {} MiB\n", device.global_memory_bytes >> 20);
        fmt::print("  double:         {}\n", device.has_fp64 ? "yes (cl_khr_fp64)" : "no");
        fmt::print("  packet width:   {} rays per work-item\n", preferred_packet_width(device));
    }
    return 0;
}

}  // namespace fgr
