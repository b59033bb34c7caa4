// SPDX-License-Identifier: Apache-2.0
#pragma once
// A test suite's OpenCL device and memory-only kernel cache (hermetic: nothing on disk), opened
// once for the suite's tests and closed after them. Derive a fixture from DeviceSuite<> (or
// DeviceSuite<::testing::TestWithParam<P>>) and use device_ and cache_. Tests outside a fixture
// use shared_device().

#include <gtest/gtest.h>

#include <filesystem>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"

namespace fgr::test {

// The OpenCL device of the tests that have no fixture: opened on first use, kept until the process
// ends.
inline ComputeDevice& shared_device() {
    static ComputeDevice opened = open_device(-1);
    return opened;
}

template <typename Base = ::testing::Test>
class DeviceSuite : public Base {
protected:
    static void SetUpTestSuite() {
        device_ = new ComputeDevice(open_device(-1));
        cache_ = new ProgramCache(std::filesystem::path());
    }
    static void TearDownTestSuite() {
        delete cache_;
        delete device_;
        cache_ = nullptr;
        device_ = nullptr;
    }

    static inline ComputeDevice* device_ = nullptr;
    static inline ProgramCache* cache_ = nullptr;
};

}  // namespace fgr::test
