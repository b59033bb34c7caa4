# SPDX-License-Identifier: Apache-2.0
# The CMake package scene authors build against: `find_package(fgr)` gives the target
# fgr::plugin_api (the plugin ABI headers) and the function fgr_add_scene_plugin(). Installed
# into <prefix>/<libdir>/cmake/fgr; the build tree gets the same files under the same relative
# path, so a scene can also be built against a build of fgr that was never installed.
include(CMakePackageConfigHelpers)

write_basic_package_version_file(${CMAKE_BINARY_DIR}/${FGR_INSTALL_CMAKE_DIR}/fgrConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)

# Installed: targets from the export set, helper scripts beside the config.
install(TARGETS fgr_plugin_api EXPORT fgrTargets COMPONENT sdk)
install(EXPORT fgrTargets NAMESPACE fgr:: DESTINATION ${FGR_INSTALL_CMAKE_DIR} COMPONENT sdk)
set(FGR_CONFIG_KERNEL_DIR ${FGR_INSTALL_KERNEL_DIR})
set(FGR_CONFIG_EXECUTABLE ${CMAKE_INSTALL_BINDIR}/fgr${CMAKE_EXECUTABLE_SUFFIX})
configure_package_config_file(cmake/fgrConfig.cmake.in
    ${CMAKE_BINARY_DIR}/fgrConfig-install.cmake
    INSTALL_DESTINATION ${FGR_INSTALL_CMAKE_DIR}
    PATH_VARS FGR_CONFIG_KERNEL_DIR FGR_CONFIG_EXECUTABLE)
install(FILES ${CMAKE_BINARY_DIR}/fgrConfig-install.cmake DESTINATION ${FGR_INSTALL_CMAKE_DIR}
    RENAME fgrConfig.cmake COMPONENT sdk)
install(FILES ${CMAKE_BINARY_DIR}/${FGR_INSTALL_CMAKE_DIR}/fgrConfigVersion.cmake
    cmake/FgrScenePlugin.cmake cmake/FgrInstallScene.cmake cmake/embed.cmake
    DESTINATION ${FGR_INSTALL_CMAKE_DIR} COMPONENT sdk)

# Build tree: the same config, pointing at the source tree's headers and kernels.
export(EXPORT fgrTargets NAMESPACE fgr::
    FILE ${CMAKE_BINARY_DIR}/${FGR_INSTALL_CMAKE_DIR}/fgrTargets.cmake)
set(FGR_CONFIG_KERNEL_DIR ${PROJECT_SOURCE_DIR}/kernels)
set(FGR_CONFIG_EXECUTABLE ${CMAKE_RUNTIME_OUTPUT_DIRECTORY}/fgr${CMAKE_EXECUTABLE_SUFFIX})
configure_package_config_file(cmake/fgrConfig.cmake.in
    ${CMAKE_BINARY_DIR}/${FGR_INSTALL_CMAKE_DIR}/fgrConfig.cmake
    INSTALL_DESTINATION ${CMAKE_BINARY_DIR}/${FGR_INSTALL_CMAKE_DIR}
    INSTALL_PREFIX ${CMAKE_BINARY_DIR} PATH_VARS FGR_CONFIG_KERNEL_DIR FGR_CONFIG_EXECUTABLE)
foreach(script FgrScenePlugin.cmake FgrInstallScene.cmake embed.cmake)
    configure_file(cmake/${script} ${CMAKE_BINARY_DIR}/${FGR_INSTALL_CMAKE_DIR}/${script} COPYONLY)
endforeach()

# The SDK (its pointer page README.md, the template, the examples and their images) and the ABI,
# for scene authors to read beside the kernel library's source (installed by
# kernels/CMakeLists.txt). The guide's links resolve in the install as in the source tree
# (tests/installed_docs.sh): ABI.md keeps its place beside sdk/, the examples' images their place
# in sdk/.
file(GLOB sdk_images ${PROJECT_SOURCE_DIR}/sdk/*.png)
install(FILES sdk/README.md ${sdk_images} DESTINATION ${CMAKE_INSTALL_DATADIR}/fgr/sdk COMPONENT sdk)
install(FILES plugin_api/ABI.md DESTINATION ${CMAKE_INSTALL_DATADIR}/fgr/plugin_api
    COMPONENT sdk)
install(DIRECTORY sdk/template sdk/examples DESTINATION ${CMAKE_INSTALL_DATADIR}/fgr/sdk
    COMPONENT sdk)
# The guide itself, the documentation site's SDK pages, goes beside sdk/ as it lies beside it in the
# source tree (docs/sdk/), so its links to the examples' images and the ABI resolve in both.
install(DIRECTORY docs/sdk/ DESTINATION ${CMAKE_INSTALL_DATADIR}/fgr/docs/sdk COMPONENT sdk)
