// SPDX-License-Identifier: Apache-2.0
#pragma once
// The device buffer a frame's kernels write their planes into, and how the host reads it back.
// It outlives the frame: a renderer keeps one and reuses it while frames fit, so a device that
// pins host memory for a read-back pins it once, not every frame.

#include <CL/opencl.hpp>
#include <cstddef>
#include <span>

#include "device/opencl_device.hpp"

namespace fgr {

// How the host sees the planes once the kernels are done.
enum class HostView {
    // The buffer itself, mapped: on a CPU device it is host memory already, and a copy (into
    // pages touched for the first time) took as long as unpacking it.
    Mapped,
    // Copied into a pinned host buffer (CL_MEM_ALLOC_HOST_PTR, mapped once): a GPU driver's map
    // of a device buffer stages it through host memory of its own, which it pins per buffer.
    Staged,
};

class FramePlanes {
public:
    FramePlanes(const ComputeDevice& device, HostView view);
    FramePlanes(const FramePlanes&) = delete;
    FramePlanes& operator=(const FramePlanes&) = delete;
    ~FramePlanes();

    // The view that suits a device: Mapped on CPUs, Staged on the rest.
    static HostView preferred_view(const DeviceInfo& info);

    // The device buffer, holding at least `floats` values; its contents are undefined. Ends the
    // host's view of the last frame.
    const cl::Buffer& reserve(size_t floats);

    // The first `floats` values of the buffer on the host, after the queue's work before this
    // call; valid until the next reserve() or read().
    std::span<const float> read(size_t floats);

private:
    void unmap_buffer();
    void unmap(const cl::Buffer& buffer, float* view);

    const ComputeDevice& device_;
    HostView view_;
    cl::Buffer buffer_;
    size_t capacity_ = 0;      // floats
    float* mapped_ = nullptr;  // Mapped: buffer_ while the host reads it
    cl::Buffer staging_;       // Staged: the pinned copy, mapped for the renderer's life
    size_t staging_capacity_ = 0;
    float* staged_ = nullptr;
};

}  // namespace fgr
