// SPDX-License-Identifier: Apache-2.0
#include "device/opencl_device.hpp"

#include <spdlog/spdlog.h>

#include <stdexcept>

namespace fgr {
namespace {

// CL string queries end with a NUL the C++ wrapper keeps; trim it and trailing spaces.
std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\0' || text.back() == ' ')) text.pop_back();
    return text;
}

DeviceInfo describe(const cl::Platform& platform, const cl::Device& device, int index) {
    DeviceInfo info;
    info.index = index;
    info.platform = trimmed(platform.getInfo<CL_PLATFORM_NAME>());
    info.name = trimmed(device.getInfo<CL_DEVICE_NAME>());
    info.vendor = trimmed(device.getInfo<CL_DEVICE_VENDOR>());
    info.version = trimmed(device.getInfo<CL_DEVICE_VERSION>());
    info.driver_version = trimmed(device.getInfo<CL_DRIVER_VERSION>());
    info.opencl_c_version = trimmed(device.getInfo<CL_DEVICE_OPENCL_C_VERSION>());
    const auto type = device.getInfo<CL_DEVICE_TYPE>();
    info.is_cpu = (type & CL_DEVICE_TYPE_CPU) != 0;
    info.is_gpu = (type & CL_DEVICE_TYPE_GPU) != 0;
    info.compute_units = device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
    info.global_memory_bytes = device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
    info.has_fp64 = device.getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_fp64") != std::string::npos;
    return info;
}

struct FoundDevice {
    DeviceInfo info;
    cl::Device device;
};

std::vector<FoundDevice> enumerate() {
    std::vector<FoundDevice> found;
    std::vector<cl::Platform> platforms;
    // No ICD installed reports CL_PLATFORM_NOT_FOUND_KHR: that is "no devices", not a crash.
    if (cl::Platform::get(&platforms) != CL_SUCCESS) return found;
    for (const auto& platform : platforms) {
        std::vector<cl::Device> devices;
        try {
            platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
        } catch (const cl::Error& error) {
            spdlog::debug("platform has no usable devices: {}", cl_error_name(error.err()));
            continue;
        }
        for (const auto& device : devices) {
            found.push_back({describe(platform, device, static_cast<int>(found.size())), device});
        }
    }
    return found;
}

}  // namespace

std::vector<DeviceInfo> list_devices() {
    std::vector<DeviceInfo> infos;
    try {
        for (auto& found : enumerate()) infos.push_back(std::move(found.info));
    } catch (const cl::Error& error) {
        spdlog::warn("OpenCL enumeration failed: {} {}", error.what(), cl_error_name(error.err()));
    }
    return infos;
}

ComputeDevice open_device(int index) {
    std::vector<FoundDevice> found;
    try {
        found = enumerate();
    } catch (const cl::Error& error) {
        throw std::runtime_error("OpenCL enumeration failed: " + cl_error_name(error.err()));
    }
    if (found.empty()) {
        throw std::runtime_error(
            "no OpenCL device found (install an OpenCL driver, e.g. pocl-opencl-icd)");
    }
    if (index >= static_cast<int>(found.size())) {
        throw std::runtime_error("no OpenCL device " + std::to_string(index) + " (found " +
                                 std::to_string(found.size()) + "; see `fgr info`)");
    }
    if (index < 0) {
        index = 0;
        for (const auto& candidate : found) {
            if (candidate.info.is_gpu) {
                index = candidate.info.index;
                break;
            }
        }
    }
    ComputeDevice result;
    result.info = found[index].info;
    result.device = found[index].device;
    try {
        result.context = cl::Context(result.device);
        result.queue = cl::CommandQueue(result.context, result.device);
    } catch (const cl::Error& error) {
        throw std::runtime_error("cannot open OpenCL device " + result.info.name + ": " +
                                 cl_error_name(error.err()));
    }
    return result;
}

int preferred_packet_width(const DeviceInfo& info) { return info.is_cpu ? 16 : 1; }

std::string cl_error_name(int code) {
    const char* name = "unknown OpenCL error";
    switch (code) {
        case CL_DEVICE_NOT_FOUND:
            name = "CL_DEVICE_NOT_FOUND";
            break;
        case CL_DEVICE_NOT_AVAILABLE:
            name = "CL_DEVICE_NOT_AVAILABLE";
            break;
        case CL_COMPILER_NOT_AVAILABLE:
            name = "CL_COMPILER_NOT_AVAILABLE";
            break;
        case CL_MEM_OBJECT_ALLOCATION_FAILURE:
            name = "CL_MEM_OBJECT_ALLOCATION_FAILURE";
            break;
        case CL_OUT_OF_RESOURCES:
            name = "CL_OUT_OF_RESOURCES";
            break;
        case CL_OUT_OF_HOST_MEMORY:
            name = "CL_OUT_OF_HOST_MEMORY";
            break;
        case CL_MAP_FAILURE:
            name = "CL_MAP_FAILURE";
            break;
        case CL_INVALID_DEVICE:
            name = "CL_INVALID_DEVICE";
            break;
        case CL_INVALID_CONTEXT:
            name = "CL_INVALID_CONTEXT";
            break;
        case CL_INVALID_COMMAND_QUEUE:
            name = "CL_INVALID_COMMAND_QUEUE";
            break;
        case CL_INVALID_MEM_OBJECT:
            name = "CL_INVALID_MEM_OBJECT";
            break;
        case CL_INVALID_OPERATION:
            name = "CL_INVALID_OPERATION";
            break;
        case CL_INVALID_GLOBAL_WORK_SIZE:
            name = "CL_INVALID_GLOBAL_WORK_SIZE";
            break;
        case CL_BUILD_PROGRAM_FAILURE:
            name = "CL_BUILD_PROGRAM_FAILURE";
            break;
        case CL_INVALID_VALUE:
            name = "CL_INVALID_VALUE";
            break;
        case CL_INVALID_BINARY:
            name = "CL_INVALID_BINARY";
            break;
        case CL_INVALID_BUILD_OPTIONS:
            name = "CL_INVALID_BUILD_OPTIONS";
            break;
        case CL_INVALID_KERNEL_NAME:
            name = "CL_INVALID_KERNEL_NAME";
            break;
        case CL_INVALID_KERNEL_ARGS:
            name = "CL_INVALID_KERNEL_ARGS";
            break;
        case CL_INVALID_ARG_SIZE:
            name = "CL_INVALID_ARG_SIZE";
            break;
        case CL_INVALID_WORK_GROUP_SIZE:
            name = "CL_INVALID_WORK_GROUP_SIZE";
            break;
        case CL_INVALID_BUFFER_SIZE:
            name = "CL_INVALID_BUFFER_SIZE";
            break;
        case -1001:
            name = "CL_PLATFORM_NOT_FOUND_KHR";
            break;
        default:
            break;
    }
    return std::string(name) + " (" + std::to_string(code) + ")";
}

}  // namespace fgr
