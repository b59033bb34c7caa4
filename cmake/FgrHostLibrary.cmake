# SPDX-License-Identifier: Apache-2.0
# fgr_host_library(NAME [OPENCL] SOURCE...): one concept of the host, host/<concept>/, as a static
# library; OPENCL when it uses the OpenCL C++ bindings (they are precompiled with its headers).
# Its headers sit beside its sources and are included from host/ as "<concept>/<file>.hpp"; what a
# concept may use is what it links (target_link_libraries), checked by tests/architecture_check.sh.
# Position-independent, since the viewer and video modules link the engine into shared objects.
function(fgr_host_library target)
    cmake_parse_arguments(ARG "OPENCL" "" "" ${ARGN})
    add_library(${target} STATIC ${ARG_UNPARSED_ARGUMENTS})
    target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR}/host)
    target_link_libraries(${target} PRIVATE fgr_warnings)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    if(ARG_OPENCL)
        fgr_precompile_headers(${target} <CL/opencl.hpp>)
    else()
        fgr_precompile_headers(${target})
    endif()
endfunction()
