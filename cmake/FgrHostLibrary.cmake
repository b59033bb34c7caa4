# SPDX-License-Identifier: Apache-2.0
# fgr_host_library(NAME [OPENCL] [OWN_PRECOMPILED_HEADER] SOURCE...): one concept of the host,
# host/<concept>/, as a static library; OPENCL when it uses the OpenCL C++ bindings (they are
# precompiled with its headers); OWN_PRECOMPILED_HEADER when a package it uses defines macros the
# standard headers test (SDL2's _REENTRANT), so it cannot share the host's precompiled header.
# Its headers sit beside its sources and are included from host/ as "<concept>/<file>.hpp"; what a
# concept may use is what it links (target_link_libraries), checked by tests/architecture_check.sh.
# Position-independent, since the viewer and video modules link the engine into shared objects.
function(fgr_host_library target)
    cmake_parse_arguments(ARG "OPENCL;OWN_PRECOMPILED_HEADER" "" "" ${ARGN})
    add_library(${target} STATIC ${ARG_UNPARSED_ARGUMENTS})
    target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR}/host)
    target_link_libraries(${target} PRIVATE fgr_warnings)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    set(opencl_headers)
    if(ARG_OPENCL)
        set(opencl_headers <CL/opencl.hpp>)
    endif()
    if(ARG_OWN_PRECOMPILED_HEADER)
        fgr_precompile_headers(${target} ${opencl_headers})
    elseif(FGR_PRECOMPILE_HEADERS AND ARG_OPENCL)
        target_precompile_headers(${target} REUSE_FROM fgr_host_pch_opencl)
    elseif(FGR_PRECOMPILE_HEADERS)
        target_precompile_headers(${target} REUSE_FROM fgr_host_pch_common)
    endif()
endfunction()

# The host libraries share two precompiled headers, the common headers with the OpenCL bindings
# and without, each built once by a library of its own that holds nothing else, instead of once
# per library: building one takes 10 to 17 s of compiler time. GCC uses a precompiled header only
# where the compile has every macro the header was built with, defined the same way (the
# libraries' own definitions come on top), and -Winvalid-pch with -Werror makes a mismatch fail the
# build instead of quietly parsing the headers again. So these libraries have exactly what every
# host library has: the global definitions, position-independent code, fgr's warnings, and the
# definitions of fmt and spdlog, which fgr_util passes on to all of them.
function(fgr_host_pch_library target)
    add_library(${target} STATIC ${PROJECT_SOURCE_DIR}/cmake/host_pch.cpp)
    target_link_libraries(${target} PRIVATE fgr_warnings fmt::fmt spdlog::spdlog glm::glm
        ${ARGN})
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
# Called where the host's libraries are made (host/CMakeLists.txt), after every global setting.
function(fgr_host_precompiled_headers)
    if(FGR_PRECOMPILE_HEADERS)
        fgr_host_pch_library(fgr_host_pch_common)
        fgr_precompile_headers(fgr_host_pch_common)
        fgr_host_pch_library(fgr_host_pch_opencl OpenCL::OpenCL)
        fgr_precompile_headers(fgr_host_pch_opencl <CL/opencl.hpp>)
    endif()
endfunction()
