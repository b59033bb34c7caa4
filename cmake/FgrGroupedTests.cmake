# SPDX-License-Identifier: Apache-2.0
# fgr_add_grouped_gtests(TARGET NAME name FILTER filter GROUP_SIZE n
#                        [TIMEOUT seconds] [LABELS label...] [ENVIRONMENT VAR=value...])
#
# Registers TARGET's GoogleTest cases that FILTER selects as ctest tests of up to GROUP_SIZE cases
# each, one process per group, where gtest_discover_tests makes one process per case. A test
# process pays for its start before any case runs: loading ~170 shared libraries, the parametrized
# suites' tables, and under the sanitizers their runtimes' start and LeakSanitizer's scan at exit
# (0.4 s a process, a third of the sanitizer job's time). Consecutive suites share a group while
# they fit, and a suite larger than a group is split, so a test's name says which cases it runs:
# `Suite`, `First..Last` (the suites from First to Last in the binary's order) or `Suite#2/3`.
# One case alone runs with `TARGET --gtest_filter=Suite.Case`.
#
# Like gtest_discover_tests (POST_BUILD mode), the cases are listed after each build of TARGET
# (FgrGroupGTests.cmake) and ctest reads the groups from the file that writes.
function(fgr_add_grouped_gtests target)
    cmake_parse_arguments(PARSE_ARGV 1 arg "" "NAME;FILTER;GROUP_SIZE;TIMEOUT" "LABELS;ENVIRONMENT")
    if(NOT arg_NAME OR NOT arg_FILTER OR NOT arg_GROUP_SIZE)
        message(FATAL_ERROR "fgr_add_grouped_gtests: NAME, FILTER and GROUP_SIZE are required")
    endif()
    set(prefix "${CMAKE_CURRENT_BINARY_DIR}/${target}_${arg_NAME}")
    set(groups_file "${prefix}_groups.cmake")
    set(include_file "${prefix}_include.cmake")
    add_custom_command(TARGET ${target} POST_BUILD
        BYPRODUCTS "${groups_file}"
        COMMAND "${CMAKE_COMMAND}"
            "-DTEST_EXECUTABLE=$<TARGET_FILE:${target}>"
            "-DTEST_FILTER=${arg_FILTER}"
            "-DGROUP_SIZE=${arg_GROUP_SIZE}"
            "-DWORKING_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR}"
            "-DLIST_VARIABLE=fgr_grouped_${arg_NAME}"
            "-DGROUPS_FILE=${groups_file}"
            -P "${PROJECT_SOURCE_DIR}/cmake/FgrGroupGTests.cmake"
        VERBATIM)
    set(properties "")
    if(arg_TIMEOUT)
        string(APPEND properties " TIMEOUT ${arg_TIMEOUT}")
    endif()
    if(arg_LABELS)
        string(APPEND properties " LABELS [==[${arg_LABELS}]==]")
    endif()
    if(arg_ENVIRONMENT)
        string(APPEND properties " ENVIRONMENT [==[${arg_ENVIRONMENT}]==]")
    endif()
    set(apply_properties "")
    if(properties)
        string(CONCAT apply_properties
            "  if(fgr_grouped_${arg_NAME})\n"
            "    set_tests_properties(\${fgr_grouped_${arg_NAME}} PROPERTIES${properties})\n"
            "  endif()\n")
    endif()
    # Before the first build there is no list yet: a test that says so, as gtest_discover_tests does.
    file(WRITE "${include_file}"
        "if(EXISTS [==[${groups_file}]==])\n"
        "  include([==[${groups_file}]==])\n"
        "${apply_properties}"
        "else()\n"
        "  add_test(${target}_${arg_NAME}_NOT_BUILT ${target}_${arg_NAME}_NOT_BUILT)\n"
        "endif()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
endfunction()
