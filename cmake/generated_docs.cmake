# SPDX-License-Identifier: Apache-2.0
# cmake -DFGR=... -DMAN=... -DBASH=... -DZSH=... -DREFERENCE=... -DGZIP=... -P generated_docs.cmake
# Writes what is generated from fgr's command-line definitions by the fgr just built: the man page
# (and MAN.gz, compressed reproducibly, for the package: CPack's DEB does not compress it), the
# bash and zsh completion scripts and the docs site's CLI reference. Nothing here opens an OpenCL
# device or compiles a kernel.
function(fgr_write output)
    get_filename_component(directory ${output} DIRECTORY)
    file(MAKE_DIRECTORY ${directory})
    execute_process(COMMAND ${FGR} ${ARGN} OUTPUT_FILE ${output}.tmp RESULT_VARIABLE status
                    ERROR_VARIABLE errors)
    if(NOT status EQUAL 0)
        file(REMOVE ${output}.tmp)
        message(FATAL_ERROR "`fgr ${ARGN}` failed (${status}): ${errors}")
    endif()
    file(RENAME ${output}.tmp ${output})
endfunction()

fgr_write(${MAN} __reference man)
fgr_write(${BASH} completion bash)
fgr_write(${ZSH} completion zsh)
fgr_write(${REFERENCE} __reference markdown)
# -n: no name or time stamp in the header, so the same page compresses to the same bytes.
execute_process(COMMAND ${GZIP} -9 -n -c ${MAN} OUTPUT_FILE ${MAN}.gz RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "gzip ${MAN} failed (${status})")
endif()
