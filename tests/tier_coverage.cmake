# SPDX-License-Identifier: Apache-2.0
# The ctest tests of this build run every GoogleTest case of TEST_EXECUTABLE exactly once: none is
# lost between the tiers' filters and the grouping (cmake/FgrGroupedTests.cmake), none runs twice,
# and no test names a case the binary does not have. Run with cmake -P:
#   CTEST_COMMAND, BUILD_DIR, TEST_EXECUTABLE
execute_process(COMMAND "${CTEST_COMMAND}" --test-dir "${BUILD_DIR}" --show-only=json-v1
    OUTPUT_VARIABLE registered RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "ctest --show-only failed (${result})")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/../cmake/FgrGTestListing.cmake")
fgr_list_gtest_cases(cases "${TEST_EXECUTABLE}" "*" "")

# Every case a registered test runs: the names in each --gtest_filter (exact names, joined by ':').
string(REGEX MATCHALL "\"--gtest_filter=[^\"]*\"" filters "${registered}")
set(run "")
foreach(filter IN LISTS filters)
    string(REGEX REPLACE "^\"--gtest_filter=(.*)\"$" "\\1" filter "${filter}")
    if(filter MATCHES "[*?-]")
        message(FATAL_ERROR "a test runs a pattern, not exact cases: ${filter}")
    endif()
    string(REPLACE ":" ";" names "${filter}")
    list(APPEND run ${names})
endforeach()

# report(WHAT NAME...): a line of problems naming the cases, when there are any.
set(problems "")
function(report what)
    if(ARGN)
        list(JOIN ARGN ", " names)
        string(APPEND problems "${what}: ${names}\n")
        set(problems "${problems}" PARENT_SCOPE)
    endif()
endfunction()

set(unique_run ${run})
list(REMOVE_DUPLICATES unique_run)
# What is left of every run once each case is taken out once: the cases run twice or more.
set(twice ${run})
foreach(name IN LISTS unique_run)
    list(FIND twice "${name}" at)
    list(REMOVE_AT twice ${at})
endforeach()
list(REMOVE_DUPLICATES twice)
report("run by more than one test" ${twice})
set(missing ${cases})
list(REMOVE_ITEM missing ${unique_run})
report("run by no test" ${missing})
set(unknown ${unique_run})
list(REMOVE_ITEM unknown ${cases})
report("not in ${TEST_EXECUTABLE}" ${unknown})
if(problems)
    message(FATAL_ERROR "${problems}")
endif()
list(LENGTH cases case_count)
message(STATUS "each of the ${case_count} cases runs in exactly one test")
