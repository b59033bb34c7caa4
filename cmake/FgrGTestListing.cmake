# SPDX-License-Identifier: Apache-2.0
# fgr_list_gtest_cases(OUT EXECUTABLE FILTER WORKING_DIRECTORY): OUT gets the GoogleTest cases
# EXECUTABLE runs under FILTER ("*" for all), as "Suite.Case" in the binary's order, DISABLED_
# cases left out. For cmake -P scripts (FgrGroupGTests.cmake, tests/tier_coverage.cmake).
function(fgr_list_gtest_cases out executable filter working_directory)
    if(NOT working_directory)
        set(working_directory ".")
    endif()
    execute_process(
        COMMAND "${executable}" --gtest_list_tests "--gtest_filter=${filter}"
        WORKING_DIRECTORY "${working_directory}"
        OUTPUT_VARIABLE listing
        ERROR_VARIABLE errors
        RESULT_VARIABLE result
        TIMEOUT 120)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "${executable} --gtest_list_tests failed (${result}):\n${errors}")
    endif()
    # The listing: a suite's line ("Suite." or "Prefix/Suite.", maybe "  # TypeParam = ..."),
    # then its cases indented by two spaces ("  Case" or "  Case/param  # GetParam() = ...").
    # The comments, which may hold brackets and semicolons, go before the lines become a list.
    string(REGEX REPLACE "  #[^\n]*" "" listing "${listing}")
    string(REPLACE ";" "" listing "${listing}")
    string(REPLACE "\n" ";" lines "${listing}")
    set(cases "")
    set(suite "")
    foreach(line IN LISTS lines)
        if(line MATCHES "^([^ ]+\\.)$")
            set(suite "${CMAKE_MATCH_1}")
        elseif(line MATCHES "^  ([^ ]+)$")
            set(case "${CMAKE_MATCH_1}")
            if(NOT suite STREQUAL "" AND NOT case MATCHES "^DISABLED_")
                list(APPEND cases "${suite}${case}")
            endif()
        endif()
    endforeach()
    set(${out} "${cases}" PARENT_SCOPE)
endfunction()
