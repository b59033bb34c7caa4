# SPDX-License-Identifier: Apache-2.0
# Debian packages (./build.sh package, docs/packages.md): CPack's DEB generator makes one package
# per install component.
#
#   renderer  fgr          bin/fgr, the built-in scenes, the kernel library's source, the schemas,
#                          the man page and completions, the licence files
#   viewer    fgr-viewer   libfgr_viewer.so, `fgr view`
#   video     fgr-video    libfgr_video_ffmpeg.so, `fgr video`
#   mpi       fgr-mpi      libfgr_mpi.so, `mpirun -np N fgr render|video`
#   sdk       fgr-sdk      the plugin ABI headers, the CMake package, the scene template, the
#                          examples and the guide
#
# CPack rather than a debian/ folder: the packages are the install() rules' components, so what
# goes into which package is said once, in the CMake files that build it, and `./build.sh package`
# packs the build tree CI has just built and tested. debhelper would want a Debian source package
# (debian/control, rules, changelog and *.install lists that must agree with the install rules)
# and a build of its own; fgr ships binary packages, not a source package for the archive.
#
# Depends come from dpkg-shlibdeps (CPACK_DEBIAN_PACKAGE_SHLIBDEPS): each package needs exactly the
# runtime libraries its files link, never their -dev packages. tests/package/ installs the
# packages into a clean Debian root to check them.

# Each package's copyright file (Debian policy 12.5): fgr's licence, pointing at
# /usr/share/common-licenses/Apache-2.0, and the third-party licences of what that package's
# files link or include, from the fragments in packaging/copyright/.
set(fgr_copyright_sources ${PROJECT_SOURCE_DIR}/packaging/copyright)
# fgr_package_copyright(COMPONENT PACKAGE SUMMARY FRAGMENT...)
function(fgr_package_copyright component package summary)
    set(PACKAGE ${package})
    set(SUMMARY ${summary})
    configure_file(${fgr_copyright_sources}/head.txt ${CMAKE_BINARY_DIR}/packaging/${package}/copyright
        @ONLY)
    set(out ${CMAKE_BINARY_DIR}/packaging/${package}/copyright)
    foreach(fragment ${ARGN})
        file(READ ${fgr_copyright_sources}/${fragment} text)
        file(APPEND ${out} "${text}")
    endforeach()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${fgr_copyright_sources}/head.txt)
    foreach(fragment ${ARGN})
        set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
            ${fgr_copyright_sources}/${fragment})
    endforeach()
    install(FILES ${out} DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/${package}
        COMPONENT ${component})
endfunction()

fgr_package_copyright(renderer fgr "a real-time renderer of 3D fractals" renderer.txt
    licence-expat.txt licence-bsd-3-clause.txt)
# Licences, the trust model and the third-party licences, for every install of fgr.
install(FILES LICENSE NOTICE SECURITY.md docs/third-party-licences.md
    DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/fgr COMPONENT renderer)
if(EXISTS ${PROJECT_SOURCE_DIR}/CHANGES.md)
    install(FILES CHANGES.md DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/fgr COMPONENT renderer)
endif()
set(fgr_package_components renderer sdk)
fgr_package_copyright(sdk fgr-sdk "fgr's kit for writing scene plugins" sdk.txt)
if(TARGET fgr_viewer_module)
    list(APPEND fgr_package_components viewer)
    fgr_package_copyright(viewer fgr-viewer "fgr's interactive viewer" viewer.txt
        licence-expat.txt)
endif()
if(TARGET fgr_video_ffmpeg)
    list(APPEND fgr_package_components video)
    fgr_package_copyright(video fgr-video "video encoding for fgr" video.txt licence-expat.txt)
endif()
if(TARGET fgr_mpi)
    list(APPEND fgr_package_components mpi)
    fgr_package_copyright(mpi fgr-mpi "MPI support for fgr" mpi.txt licence-expat.txt)
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME fgr)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "The fgr authors")
set(CPACK_PACKAGE_CONTACT "The fgr authors")
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/packages)
# The build tree keeps whatever prefix it was configured with (the tests install it elsewhere);
# the packages install under /usr. The paths fgr finds its plugins, modules and schemas by are
# relative to bin/ (host/scene/CMakeLists.txt), so they hold under any prefix; ./build.sh
# configures with CMAKE_INSTALL_PREFIX=/usr so GNUInstallDirs picks Debian's multiarch libdir.
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_COMPONENTS_ALL ${fgr_package_components})
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The packages' own modules and plugins are found by fgr, not by the dynamic loader.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
# fgr (= this version) for every package but fgr: a module or the SDK from another build is
# refused (host/scene/modules.hpp), so they move in step.
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
foreach(component viewer video mpi sdk)
    set(CPACK_COMPONENT_${component}_DEPENDS renderer)  # read upper-cased below
    string(TOUPPER ${component} upper)
    set(CPACK_COMPONENT_${upper}_DEPENDS renderer)
endforeach()

set(CPACK_DEBIAN_RENDERER_PACKAGE_NAME fgr)
# shlibdeps names the ICD loader (libOpenCL.so.1, ocl-icd-libopencl1); the loader needs a driver.
# PoCL runs on any CPU; opencl-icd is the virtual package every Debian OpenCL driver provides.
set(CPACK_DEBIAN_RENDERER_PACKAGE_DEPENDS "pocl-opencl-icd | opencl-icd")
set(CPACK_COMPONENT_RENDERER_DESCRIPTION
    "real-time renderer of 3D fractals\n fgr renders 3D fractals (Mandelbulbs, boxes, IFS and more) with OpenCL: stills,\n tiled posters and, with fgr-video, videos; with fgr-viewer, interactively.")
set(CPACK_DEBIAN_VIEWER_PACKAGE_NAME fgr-viewer)
set(CPACK_COMPONENT_VIEWER_DESCRIPTION
    "interactive viewer for fgr\n The module behind `fgr view`: an SDL2 window with a Dear ImGui panel.")
set(CPACK_DEBIAN_VIDEO_PACKAGE_NAME fgr-video)
set(CPACK_COMPONENT_VIDEO_DESCRIPTION
    "video encoding for fgr\n The module behind `fgr video`, encoding with FFmpeg's libraries.")
set(CPACK_DEBIAN_MPI_PACKAGE_NAME fgr-mpi)
set(CPACK_COMPONENT_MPI_DESCRIPTION
    "MPI support for fgr\n The module that shares one render between the ranks of\n `mpirun -np N fgr render|video`.")
set(CPACK_DEBIAN_SDK_PACKAGE_NAME fgr-sdk)
# Building a scene needs CMake, a build tool for it and a C compiler (the template is C and
# OpenCL C; no C++), so they are Depends, not Recommends: fgr-sdk's files are a CMake package and C
# headers, of no use without them (cmake itself only recommends make). The C library's headers come
# with the compiler (gcc recommends libc6-dev, which apt installs by default); no -dev package is
# named here.
set(CPACK_DEBIAN_SDK_PACKAGE_DEPENDS "cmake (>= 3.20), make | ninja-build, gcc | c-compiler")
set(CPACK_COMPONENT_SDK_DESCRIPTION
    "kit for writing fgr scene plugins\n The plugin ABI headers, the CMake package (find_package(fgr)), the scene\n template, example scenes and the guide.")
# Manual pages are gzipped in the packages (Debian policy), plain in a `cmake --install`.
set(CPACK_PRE_BUILD_SCRIPTS ${PROJECT_SOURCE_DIR}/cmake/FgrCompressManPages.cmake)
include(CPack)
