#!/usr/bin/env bash
# Sets up, builds and runs fgr on Debian 12. The two Quick start commands of the README:
#
#   ./build.sh render   install what is missing, build, render the default scene to mandelbulb.png
#   ./build.sh test     install what is missing, build with warnings as errors, run every test
#                       (what CI runs)
#
# and for CI's second job:
#
#   ./build.sh test-sanitize   build with AddressSanitizer + UndefinedBehaviorSanitizer in its own
#                              tree and run the tests there (any report fails them)
#
# Needs root or sudo only when packages are missing. BUILD_DIR (default: build) picks the build
# tree, SANITIZE_BUILD_DIR (default: build-sanitize) the sanitizer build's.
set -euo pipefail

repo=$(cd "$(dirname "$0")" && pwd)
build_dir=${BUILD_DIR:-$repo/build}
sanitize_build_dir=${SANITIZE_BUILD_DIR:-$repo/build-sanitize}
jobs=$(nproc)

# Debian packages fgr needs to build and test: compiler and build tools, OpenCL (PoCL runs it on
# the CPU), the libraries named in the README, and for the viewer SDL2, Dear ImGui and OpenGL
# (Mesa's software rasteriser under the virtual X server the viewer tests run in), FFmpeg's
# libraries for `fgr video`, and Open MPI (optional to build fgr; with it, `mpirun -np N fgr render`
# shares a render between ranks, and CI tests that).
packages=(
    cmake ninja-build g++ pkg-config
    ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers pocl-opencl-icd clinfo
    libspdlog-dev libfmt-dev libglm-dev libpng-dev libcli11-dev libgtest-dev nlohmann-json3-dev
    libopenexr-dev libstb-dev libtiff-dev zlib1g-dev
    libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
    libopenmpi-dev openmpi-bin
    libsdl2-dev libimgui-dev libgl-dev libgl1-mesa-dri
    xvfb xauth gnuplot-nox
)

install_missing_packages() {
    local missing=()
    for package in "${packages[@]}"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
            missing+=("$package")
    done
    [[ ${#missing[@]} -eq 0 ]] && return 0
    echo "build.sh: installing ${missing[*]}" >&2
    local sudo=()
    [[ $(id -u) -eq 0 ]] || sudo=(sudo)
    "${sudo[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# build DIR [CMAKE_OPTION...]: configure (Release unless an option says otherwise) and build in DIR.
build() {
    local dir=$1
    shift
    cmake -S "$repo" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
    cmake --build "$dir" -j "$jobs"
}

command=${1:-render}
case "$command" in
    render)
        install_missing_packages
        build "$build_dir" -DFGR_WERROR=OFF
        "$build_dir/bin/fgr" render mandelbulb -o "${2:-mandelbulb.png}"
        ;;
    test)
        install_missing_packages
        # CI's build: any compiler warning fails it.
        build "$build_dir" -DFGR_WERROR=ON
        # Each test case runs as its own process; two at a time keeps a 2-core machine busy.
        ctest --test-dir "$build_dir" --output-on-failure -j "$jobs"
        ;;
    test-sanitize)
        install_missing_packages
        # Instrumented throughout (FGR_SANITIZE); the runtimes' options and the third-party
        # suppressions are in sanitizers/. A report ends the test's process with exit code 86.
        # The drivers' caches are the plain build's where it has one (./build.sh test, CI): PoCL's
        # kernels do not depend on the sanitizers, so none is compiled twice (tests/CMakeLists.txt).
        driver_cache=()
        [[ -d $build_dir/test-cache ]] && driver_cache=(-DFGR_TEST_DRIVER_CACHE="$build_dir/test-cache")
        build "$sanitize_build_dir" -DFGR_SANITIZE=ON -DFGR_WERROR=ON "${driver_cache[@]}"
        # A failed test runs once more: LeakSanitizer's own tracer now and then crashes while it
        # stops a process's threads at exit (PoCL keeps a pool of them), "LeakSanitizer has
        # encountered a fatal error" with no report. A real report fails both runs.
        ctest --test-dir "$sanitize_build_dir" --output-on-failure -j "$jobs" \
            --repeat until-pass:2
        ;;
    *)
        echo "usage: ./build.sh [render [OUT.png] | test | test-sanitize]" >&2
        exit 2
        ;;
esac
