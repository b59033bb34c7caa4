# Run at build time by fgr_add_grouped_gtests (FgrGroupedTests.cmake), with cmake -P:
#   TEST_EXECUTABLE, TEST_FILTER   the GoogleTest binary and the cases it selects
#   GROUP_SIZE                     the most cases a ctest test runs
#   WORKING_DIRECTORY              where the tests run
#   GROUPS_FILE, LIST_VARIABLE     the ctest file to write, and the variable it lists its tests in
# Each group runs its cases by exact name, so a group holds the cases the filter selects and no
# other, whatever else its suites hold.

execute_process(
    COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests "--gtest_filter=${TEST_FILTER}"
    WORKING_DIRECTORY "${WORKING_DIRECTORY}"
    OUTPUT_VARIABLE listing
    ERROR_VARIABLE errors
    RESULT_VARIABLE result
    TIMEOUT 120)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${result}):\n${errors}")
endif()

# The listing: a suite's line ("Suite." or "Prefix/Suite.", maybe "  # TypeParam = ..."), then
# its cases indented by two spaces ("  Case" or "  Case/param  # GetParam() = ..."). Brackets and
# semicolons in the comments are removed before the lines become a CMake list.
string(REGEX REPLACE "  #[^\n]*" "" listing "${listing}")
string(REPLACE ";" "" listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")

set(suites "")
set(suite "")
foreach(line IN LISTS lines)
    if(line MATCHES "^  ([^ ]+)$")
        set(case "${CMAKE_MATCH_1}")
        if(suite STREQUAL "" OR case MATCHES "^DISABLED_")
            continue()
        endif()
        list(APPEND cases_of_${suite} "${name_of_${suite}}.${case}")
    elseif(line MATCHES "^([^ ]+)\\.$")
        # A variable's name from the suite's ("Cli/CliBadInput" -> "Cli_CliBadInput").
        set(name "${CMAKE_MATCH_1}")
        string(MAKE_C_IDENTIFIER "${name}" suite)
        set(name_of_${suite} "${name}")
        set(cases_of_${suite} "")
        list(APPEND suites "${suite}")
    endif()
endforeach()

set(content "# Written by FgrGroupGTests.cmake after each build of the tests; do not edit.\n")
string(APPEND content "set(${LIST_VARIABLE} \"\")\n")
set(group_names "")

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
    if(count EQUAL 0)
        continue()
    endif()
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
