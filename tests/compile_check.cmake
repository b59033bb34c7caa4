# SPDX-License-Identifier: Apache-2.0
# Compiles one source file and checks the outcome, for tests that a header refuses bad code at
# compile time (ctest: cmake -P compile_check.cmake with the variables below).
#   COMPILER   the compiler to run
#   LANGUAGE   c or c++ (-x LANGUAGE)
#   STANDARD   e.g. c11, c++11
#   INCLUDE    the include directory
#   SOURCE     the file
#   DEFINE     a macro to define, or empty
#   EXPECT     "success", or a text the compiler's output must contain when it fails
set(args -x ${LANGUAGE} -std=${STANDARD} -fsyntax-only -Wall -Wextra -I${INCLUDE} ${SOURCE})
if(DEFINE)
    list(APPEND args -D${DEFINE})
endif()
execute_process(COMMAND ${COMPILER} ${args} RESULT_VARIABLE result OUTPUT_VARIABLE out
    ERROR_VARIABLE out)
if(EXPECT STREQUAL "success")
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "expected ${SOURCE} (${DEFINE}) to compile as ${STANDARD}:\n${out}")
    endif()
    return()
endif()
if(result EQUAL 0)
    message(FATAL_ERROR "expected ${SOURCE} (${DEFINE}) to fail to compile as ${STANDARD}")
endif()
string(FIND "${out}" "${EXPECT}" found)
if(found EQUAL -1)
    message(FATAL_ERROR "the compiler refused ${SOURCE} (${DEFINE}) as ${STANDARD}, but without "
        "\"${EXPECT}\":\n${out}")
endif()
message(STATUS "refused as expected: ${EXPECT}")
