# SPDX-License-Identifier: Apache-2.0
# The host refuses a shared layout header edited on its own: a copy of kernels/shared with two of
# camera_frame's fields traded must fail host/device/kernel_layout.hpp's static_asserts, and the
# unchanged copy must compile (so the refusal is the edit's). The device's side of the same edit
# is DeviceLayout.AMutatedHeaderIsCaught (tests/device/test_device_layout.cpp).
#   COMPILER  the C++ compiler
#   SHARED    kernels/shared
#   HEADER    host/device/kernel_layout.hpp
#   WORK      a scratch folder
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/unchanged ${WORK}/mutated)
file(GLOB headers ${SHARED}/*.h)
file(COPY ${headers} DESTINATION ${WORK}/unchanged)
file(COPY ${headers} DESTINATION ${WORK}/mutated)
file(READ ${SHARED}/fgr_layout_camera.h camera)
string(REPLACE "fgr_layout_int width;" "@WIDTH@" camera "${camera}")
string(REPLACE "fgr_layout_int height;" "fgr_layout_int width;" camera "${camera}")
string(REPLACE "@WIDTH@" "fgr_layout_int height;" camera "${camera}")
file(WRITE ${WORK}/mutated/fgr_layout_camera.h "${camera}")
file(WRITE ${WORK}/check.cpp "#include \"${HEADER}\"\n")

foreach(copy unchanged mutated)
    execute_process(COMMAND ${COMPILER} -x c++ -std=c++20 -fsyntax-only
        -DCL_TARGET_OPENCL_VERSION=120 -I${WORK}/${copy} ${WORK}/check.cpp
        RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
    set(result_${copy} ${result})
    set(out_${copy} "${out}")
endforeach()
file(REMOVE_RECURSE ${WORK})
if(NOT result_unchanged EQUAL 0)
    message(FATAL_ERROR "the shared headers as they are do not compile:\n${out_unchanged}")
endif()
if(result_mutated EQUAL 0)
    message(FATAL_ERROR "camera_frame's width and height traded places, and the host compiled it")
endif()
string(FIND "${out_mutated}" "offsetof(camera_frame, width)" found)
if(found EQUAL -1)
    message(FATAL_ERROR "the mutated header failed, but not on camera_frame's width:\n"
        "${out_mutated}")
endif()
message(STATUS "refused as expected: offsetof(camera_frame, width)")
