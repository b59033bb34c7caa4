// SPDX-License-Identifier: Apache-2.0
// OpenCL error codes by name (device/opencl_device.hpp): what fgr's one-line errors say when a
// driver call fails, among them the codes a GPU gives at the first call after a kernel faulted.

#include <gtest/gtest.h>

#include "device/opencl_device.hpp"

namespace fgr {
namespace {

TEST(OpenClErrors, NamesTheCodesAGpuGivesAfterAKernelFaulted) {
    EXPECT_EQ(cl_error_name(CL_INVALID_COMMAND_QUEUE), "CL_INVALID_COMMAND_QUEUE (-36)");
    EXPECT_EQ(cl_error_name(CL_OUT_OF_RESOURCES), "CL_OUT_OF_RESOURCES (-5)");
}

TEST(OpenClErrors, AnUnknownCodeKeepsItsNumber) {
    EXPECT_EQ(cl_error_name(-9999), "unknown OpenCL error (-9999)");
}

}  // namespace
}  // namespace fgr
