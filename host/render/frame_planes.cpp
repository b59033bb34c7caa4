// SPDX-License-Identifier: Apache-2.0
#include "render/frame_planes.hpp"

namespace fgr {

FramePlanes::FramePlanes(const ComputeDevice& device, HostView view)
    : device_(device), view_(view) {}

FramePlanes::~FramePlanes() {
    unmap_buffer();
    if (staged_ != nullptr) unmap(staging_, staged_);
}

HostView FramePlanes::preferred_view(const DeviceInfo& info) {
    return info.is_cpu ? HostView::Mapped : HostView::Staged;
}

const cl::Buffer& FramePlanes::reserve(size_t floats) {
    unmap_buffer();  // the kernels about to run write it
    if (floats > capacity_) {
        buffer_ = cl::Buffer(device_.context, CL_MEM_READ_WRITE, sizeof(float) * floats);
        capacity_ = floats;
    }
    return buffer_;
}

std::span<const float> FramePlanes::read(size_t floats) {
    const size_t bytes = sizeof(float) * floats;
    if (view_ == HostView::Mapped) {
        unmap_buffer();
        mapped_ = static_cast<float*>(
            device_.queue.enqueueMapBuffer(buffer_, CL_TRUE, CL_MAP_READ, 0, bytes));
        return {mapped_, floats};
    }
    if (floats > staging_capacity_) {
        if (staged_ != nullptr) unmap(staging_, staged_);
        staged_ = nullptr;
        staging_ = cl::Buffer(device_.context, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR,
                              sizeof(float) * capacity_);
        staged_ = static_cast<float*>(device_.queue.enqueueMapBuffer(
            staging_, CL_TRUE, CL_MAP_READ | CL_MAP_WRITE, 0, sizeof(float) * capacity_));
        staging_capacity_ = capacity_;
    }
    device_.queue.enqueueReadBuffer(buffer_, CL_TRUE, 0, bytes, staged_);
    return {staged_, floats};
}

void FramePlanes::unmap_buffer() {
    if (mapped_ == nullptr) return;
    unmap(buffer_, mapped_);
    mapped_ = nullptr;
}

void FramePlanes::unmap(const cl::Buffer& buffer, float* view) {
    // Nothing is read through `view` after this; an unmap that fails leaves only a mapping that
    // the buffer's release ends anyway.
    const cl_int ignored =
        clEnqueueUnmapMemObject(device_.queue(), buffer(), view, 0, nullptr, nullptr);
    static_cast<void>(ignored);
}

}  // namespace fgr
