set(FGR_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed.cmake)
# fgr_add_scene_plugin(NAME SOURCES... [CL_SOURCES file.cl...])
# Builds a scene plugin: a shared library exporting only fgr_scene_entry, written to
# ${FGR_PLUGIN_OUTPUT_DIR}. CL sources are embedded as C strings so the .so is self-contained.
function(fgr_add_scene_plugin name)
    cmake_parse_arguments(ARG "" "" "SOURCES;CL_SOURCES" ${ARGN})
    set(embedded)
    foreach(cl ${ARG_CL_SOURCES})
        get_filename_component(cl_abs ${cl} ABSOLUTE)
        get_filename_component(cl_name ${cl} NAME_WE)
        set(out ${CMAKE_CURRENT_BINARY_DIR}/${cl_name}_cl.h)
        add_custom_command(OUTPUT ${out}
            COMMAND ${CMAKE_COMMAND} -DINPUT=${cl_abs} -DOUTPUT=${out} -DVARIABLE=${cl_name}_cl
                    -P ${FGR_EMBED_SCRIPT}
            DEPENDS ${cl_abs} ${FGR_EMBED_SCRIPT}
            COMMENT "Embedding ${cl}")
        list(APPEND embedded ${out})
    endforeach()
    add_library(${name} MODULE ${ARG_SOURCES} ${embedded})
    target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_BINARY_DIR})
    target_link_libraries(${name} PRIVATE fgr_plugin_api fgr_warnings)
    set_target_properties(${name} PROPERTIES
        PREFIX "" OUTPUT_NAME "${name}"
        LIBRARY_OUTPUT_DIRECTORY ${FGR_PLUGIN_OUTPUT_DIR}
        C_VISIBILITY_PRESET hidden CXX_VISIBILITY_PRESET hidden)
endfunction()
