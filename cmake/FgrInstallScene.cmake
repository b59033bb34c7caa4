# SPDX-License-Identifier: Apache-2.0
# cmake -DPLUGIN=file.so -DDESTINATION=dir -P FgrInstallScene.cmake: copies a scene plugin into a
# plugin folder (the install-scene target of FgrScenePlugin.cmake). The copy is written under a
# hidden temporary name in the folder, which fgr's scan skips (it loads *.so), and renamed over
# the old plugin: a rename within one file system is atomic, so fgr, the viewer's reload included,
# reads the old plugin or the new one, never a half-written file.
if(NOT PLUGIN OR NOT EXISTS "${PLUGIN}")
    message(FATAL_ERROR "install-scene: no plugin to install ('${PLUGIN}')")
endif()
if(NOT DESTINATION)
    message(FATAL_ERROR "install-scene: FGR_SCENE_INSTALL_DIR is empty ($HOME was not set when "
                        "the project was configured): configure with -DFGR_SCENE_INSTALL_DIR=DIR")
endif()
file(MAKE_DIRECTORY "${DESTINATION}")
get_filename_component(name "${PLUGIN}" NAME)
# The same plugin already there stays untouched: a rebuild that changed nothing does not make a
# running viewer reload it.
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${PLUGIN}" "${DESTINATION}/${name}"
                RESULT_VARIABLE differs OUTPUT_QUIET ERROR_QUIET)
if(differs EQUAL 0)
    message(STATUS "${name} is installed in ${DESTINATION}, unchanged")
    return()
endif()
set(partial "${DESTINATION}/.${name}.partial")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy "${PLUGIN}" "${partial}" RESULT_VARIABLE copied)
if(NOT copied EQUAL 0)
    file(REMOVE "${partial}")
    message(FATAL_ERROR "install-scene: cannot copy ${PLUGIN} into ${DESTINATION}")
endif()
file(RENAME "${partial}" "${DESTINATION}/${name}")
message(STATUS "Installed ${name} into ${DESTINATION}")
