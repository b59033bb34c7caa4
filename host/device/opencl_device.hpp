// SPDX-License-Identifier: Apache-2.0
#pragma once
// OpenCL platforms and devices: enumeration for `fgr info`, and opening one device with a
// context and an in-order queue for rendering.

#include <CL/opencl.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace fgr {

struct DeviceInfo {
    int index = 0;  // position in list_devices(), counting across platforms
    std::string platform;
    std::string name;
    std::string vendor;
    std::string version;  // e.g. "OpenCL 3.0 PoCL ..."
    std::string driver_version;
    std::string opencl_c_version;  // e.g. "OpenCL C 1.2 PoCL"
    bool is_cpu = false;
    bool is_gpu = false;
    uint32_t compute_units = 0;
    uint64_t global_memory_bytes = 0;
    bool has_fp64 = false;
};

// Every device of every platform; empty when no OpenCL platform is installed.
std::vector<DeviceInfo> list_devices();

struct ComputeDevice {
    DeviceInfo info;
    cl::Device device;
    cl::Context context;
    cl::CommandQueue queue;
};

// Opens device `index` of list_devices(), or with index < 0 the first GPU, else the first device.
// Throws std::runtime_error with a one-line reason when there is no such device.
ComputeDevice open_device(int index);

// Rays per work-item that suit the device: CPUs march packets in SIMD lanes (16 measured fastest
// on AVX2 with PoCL, see docs/performance.md), GPUs one ray per work-item.
int preferred_packet_width(const DeviceInfo& info);

// A one-line name for an OpenCL error code, e.g. "CL_OUT_OF_RESOURCES (-5)".
std::string cl_error_name(int code);

}  // namespace fgr
