# SPDX-License-Identifier: Apache-2.0
# fgr_add_scene_plugin(NAME SOURCES file.c... [CL_SOURCES file.cl...])
#
# Builds the scene plugin NAME.so: a shared library that exports only fgr_scene_entry. Each
# CL source is embedded as a C array in a generated header <stem>_cl.h, as
#   static const char <stem>_cl[];       the OpenCL source, NUL-terminated
#   static const char <stem>_cl_path[];  its absolute path, for `fgr view --dev` to watch
# so the .so is self-contained. Built against an installed fgr, the build then runs `fgr check` on
# the plugin (see _fgr_check_scene_plugin below: FGR_CHECK_SCENE, FGR_COMPILE_SCENE), and the
# target install-scene copies the checked plugin into the user's plugin folder, where fgr finds it
# (see _fgr_install_scene_plugin: FGR_SCENE_INSTALL_DIR, FGR_INSTALL_SCENE_AFTER_BUILD). Used by
# fgr's own plugins (in its source tree) and by scenes built against an installed fgr
# (find_package(fgr)); the .so goes to FGR_PLUGIN_OUTPUT_DIR when that is set, else to the current
# binary directory.
set(FGR_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed.cmake)

function(fgr_add_scene_plugin name)
    cmake_parse_arguments(ARG "" "" "SOURCES;CL_SOURCES" ${ARGN})
    if(NOT ARG_SOURCES)
        message(FATAL_ERROR "fgr_add_scene_plugin(${name}): no SOURCES")
    endif()
    set(embedded)
    foreach(cl ${ARG_CL_SOURCES})
        get_filename_component(cl_abs ${cl} ABSOLUTE)
        get_filename_component(cl_name ${cl} NAME_WE)
        string(MAKE_C_IDENTIFIER ${cl_name} cl_symbol)
        set(out ${CMAKE_CURRENT_BINARY_DIR}/${cl_name}_cl.h)
        add_custom_command(OUTPUT ${out}
            COMMAND ${CMAKE_COMMAND} -DINPUT=${cl_abs} -DOUTPUT=${out} -DVARIABLE=${cl_symbol}_cl
                    -P ${FGR_EMBED_SCRIPT}
            DEPENDS ${cl_abs} ${FGR_EMBED_SCRIPT}
            COMMENT "Embedding ${cl}")
        list(APPEND embedded ${out})
    endforeach()
    add_library(${name} MODULE ${ARG_SOURCES} ${embedded})
    target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_BINARY_DIR})
    if(TARGET fgr_plugin_api)  # inside fgr's own build
        target_link_libraries(${name} PRIVATE fgr_plugin_api fgr_warnings)
    else()
        target_link_libraries(${name} PRIVATE fgr::plugin_api)
        target_compile_options(${name} PRIVATE
            $<$<C_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic>)
    endif()
    set_target_properties(${name} PROPERTIES
        PREFIX "" OUTPUT_NAME "${name}"
        C_STANDARD 11 C_STANDARD_REQUIRED ON
        C_VISIBILITY_PRESET hidden CXX_VISIBILITY_PRESET hidden)
    if(FGR_PLUGIN_OUTPUT_DIR)
        set_target_properties(${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${FGR_PLUGIN_OUTPUT_DIR})
    endif()
    if(FGR_INSTALL_PLUGIN_DIR)  # fgr's own plugins install beside the fgr binary
        install(TARGETS ${name} LIBRARY DESTINATION ${FGR_INSTALL_PLUGIN_DIR} COMPONENT renderer)
    endif()
    if(TARGET fgr_plugin_api)
        # fgr's own plugins: checked by ctest (SceneCheck.*), not while building.
        set_property(GLOBAL APPEND PROPERTY FGR_SCENE_PLUGINS ${name})
    else()
        _fgr_check_scene_plugin(${name} "${ARG_CL_SOURCES}")
        _fgr_install_scene_plugin(${name})
    endif()
endfunction()

# After a scene built against an installed fgr: `fgr check --compile` compiles its kernel, so a
# typo in the .cl fails the build with the .cl's file and line, and (FGR_CHECK_SCENE, on by
# default) `fgr check` runs its numerical checks, failing the build with a report of what to fix.
# A stamp file records success: a failed check runs again on the next build.
option(FGR_CHECK_SCENE "run `fgr check` on each scene plugin after building it" ON)
option(FGR_COMPILE_SCENE
    "compile each scene plugin's kernel after building it (`fgr check --compile`)" ON)
function(_fgr_check_scene_plugin name cl_sources)
    if(NOT FGR_COMPILE_SCENE AND NOT FGR_CHECK_SCENE)
        return()
    endif()
    if(NOT fgr_EXECUTABLE OR NOT EXISTS "${fgr_EXECUTABLE}")
        message(WARNING "fgr_add_scene_plugin(${name}): no fgr executable found (fgr_EXECUTABLE), "
                        "so the scene is not checked while building")
        return()
    endif()
    if(FGR_CHECK_SCENE)
        set(check_args check)
        set(what "Checking scene ${name} (fgr check; -DFGR_CHECK_SCENE=OFF skips)")
    else()
        set(check_args check --compile)
        set(what "Compiling the kernel of scene ${name} (fgr check --compile)")
    endif()
    set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${name}.checked)
    add_custom_command(OUTPUT ${stamp}
        COMMAND ${fgr_EXECUTABLE} ${check_args} $<TARGET_FILE:${name}>
        COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
        DEPENDS ${name} ${cl_sources}
        COMMENT "${what}"
        VERBATIM)
    add_custom_target(${name}_check ALL DEPENDS ${stamp})
endfunction()

# Into the user's plugin folder: `cmake --build build --target install-scene` copies every scene
# plugin of the project, once built and checked, into FGR_SCENE_INSTALL_DIR (by default
# ~/.local/share/fgr/plugins, the folder fgr searches after $FGR_PLUGIN_PATH and its own plugins);
# -DFGR_INSTALL_SCENE_AFTER_BUILD=ON does it on every build, so `fgr view` reloads the rebuilt scene.
# A plugin that fails its check is not copied. The copy lands under a temporary name beside the
# old plugin and is renamed over it, so an fgr that is scanning the folder sees the old file or the
# new one, never half of it.
set(FGR_SCENE_INSTALL_DIR "$ENV{HOME}/.local/share/fgr/plugins" CACHE PATH
    "where the install-scene target puts scene plugins (fgr searches ~/.local/share/fgr/plugins)")
option(FGR_INSTALL_SCENE_AFTER_BUILD
    "copy each scene plugin into FGR_SCENE_INSTALL_DIR after every build (install-scene)" OFF)
set(FGR_INSTALL_SCENE_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/FgrInstallScene.cmake)
function(_fgr_install_scene_plugin name)
    if(FGR_INSTALL_SCENE_AFTER_BUILD)
        set(all ALL)
    else()
        set(all)
    endif()
    add_custom_target(${name}_install ${all}
        COMMAND ${CMAKE_COMMAND} -DPLUGIN=$<TARGET_FILE:${name}>
                -DDESTINATION=${FGR_SCENE_INSTALL_DIR} -P ${FGR_INSTALL_SCENE_SCRIPT}
        COMMENT "Installing scene ${name} into ${FGR_SCENE_INSTALL_DIR}"
        VERBATIM)
    # After the check, when there is one: a scene that fails it stays out of the folder.
    if(TARGET ${name}_check)
        add_dependencies(${name}_install ${name}_check)
    else()
        add_dependencies(${name}_install ${name})
    endif()
    if(NOT TARGET install-scene)
        add_custom_target(install-scene)
    endif()
    add_dependencies(install-scene ${name}_install)
endfunction()
