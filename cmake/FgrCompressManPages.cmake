# SPDX-License-Identifier: Apache-2.0
# Run by CPack (CPACK_PRE_BUILD_SCRIPTS) on the staged files before it packs them: Debian ships
# manual pages compressed with gzip -9n (policy 12.1), and the install rules install them plain.
file(GLOB_RECURSE staged LIST_DIRECTORIES false "${CPACK_TEMPORARY_DIRECTORY}/*")
foreach(file ${staged})
    if(file MATCHES "/share/man/man[1-9]/[^/]+\\.[1-9]$")
        execute_process(COMMAND gzip -9nf "${file}" RESULT_VARIABLE result)
        if(NOT result EQUAL 0)
            message(FATAL_ERROR "gzip ${file} failed")
        endif()
    endif()
endforeach()
