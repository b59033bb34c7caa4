# SPDX-License-Identifier: Apache-2.0
# Run at build time by fgr_add_grouped_gtests (FgrGroupedTests.cmake), with cmake -P:
#   TEST_EXECUTABLE, TEST_FILTER   the GoogleTest binary and the cases it selects
#   GROUP_SIZE                     the most cases a ctest test runs
#   WORKING_DIRECTORY              where the tests run
#   GROUPS_FILE, LIST_VARIABLE     the ctest file to write, and the variable it lists its tests in
# Each group runs its cases by exact name, so a group holds the cases the filter selects and no
# other, whatever else its suites hold.

include("${CMAKE_CURRENT_LIST_DIR}/FgrGTestListing.cmake")
fgr_list_gtest_cases(all_cases "${TEST_EXECUTABLE}" "${TEST_FILTER}" "${WORKING_DIRECTORY}")

# The cases by suite, the suites in the binary's order; a variable's name from the suite's
# ("Cli/CliBadInput" -> "Cli_CliBadInput"). Suite names hold no '.'.
set(suites "")
foreach(case IN LISTS all_cases)
    string(FIND "${case}" "." dot)
    string(SUBSTRING "${case}" 0 ${dot} name)
    string(MAKE_C_IDENTIFIER "${name}" suite)
    if(NOT DEFINED name_of_${suite})
        set(name_of_${suite} "${name}")
        set(cases_of_${suite} "")
        list(APPEND suites "${suite}")
    endif()
    list(APPEND cases_of_${suite} "${case}")
endforeach()

set(content "# Written by FgrGroupGTests.cmake after each build of the tests; do not edit.\n")
string(APPEND content "set(${LIST_VARIABLE} \"\")\n")

# write_group(NAME CASE...): one ctest test running those cases.
function(write_group name)
    list(JOIN ARGN ":" filter)
    string(APPEND content
        "add_test([==[${name}]==] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${filter}]==])\n"
        "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY "
        "[==[${WORKING_DIRECTORY}]==])\n"
        "list(APPEND ${LIST_VARIABLE} [==[${name}]==])\n")
    set(content "${content}" PARENT_SCOPE)
endfunction()

# The group being filled: its cases and its first and last suites' names.
set(pending "")
set(pending_first "")
set(pending_last "")
macro(flush_pending)
    if(pending)
        if(pending_first STREQUAL pending_last)
            write_group("${pending_first}" ${pending})
        else()
            write_group("${pending_first}..${pending_last}" ${pending})
        endif()
        set(pending "")
    endif()
endmacro()

foreach(suite IN LISTS suites)
    set(cases ${cases_of_${suite}})
    list(LENGTH cases count)
    set(name "${name_of_${suite}}")
    if(count GREATER GROUP_SIZE)
        # A suite larger than a group: parts of nearly equal size, in the suite's order.
        flush_pending()
        math(EXPR parts "(${count} + ${GROUP_SIZE} - 1) / ${GROUP_SIZE}")
        foreach(part RANGE 1 ${parts})
            math(EXPR begin "(${part} - 1) * ${count} / ${parts}")
            math(EXPR end "${part} * ${count} / ${parts}")
            math(EXPR length "${end} - ${begin}")
            list(SUBLIST cases ${begin} ${length} part_cases)
            write_group("${name}#${part}/${parts}" ${part_cases})
        endforeach()
        continue()
    endif()
    list(LENGTH pending pending_count)
    math(EXPR together "${pending_count} + ${count}")
    if(together GREATER GROUP_SIZE)
        flush_pending()
    endif()
    if(NOT pending)
        set(pending_first "${name}")
    endif()
    set(pending_last "${name}")
    list(APPEND pending ${cases})
endforeach()
flush_pending()

# Written whole, then moved: ctest never reads half a file.
file(WRITE "${GROUPS_FILE}.tmp" "${content}")
file(RENAME "${GROUPS_FILE}.tmp" "${GROUPS_FILE}")
