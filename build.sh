#!/usr/bin/env bash
# Sets up, builds and runs fgr on Debian 12. The two Quick start commands of the README:
#
#   ./build.sh render   install what building fgr needs, build fgr and the built-in scenes (no
#                       tests), render the default scene to mandelbulb.png
#   ./build.sh test     install what the tests need too, build everything with warnings as errors,
#                       run the quick tier of the tests
#
# and the rest of what CI runs (.ci/run):
#
#   ./build.sh test-slow       the slow tier: sweeps over every scene, width or many samples, and
#                              a slice of the golden set (tests/CMakeLists.txt says which)
#   ./build.sh test-golden     the whole golden set (tests/golden/README.md): before and after a
#                              change that must leave every image as it is
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

# Debian packages fgr needs to build: compiler and build tools, OpenCL (PoCL runs it on the CPU),
# the libraries named in the README, SDL2, Dear ImGui and OpenGL for the viewer, and FFmpeg's
# libraries for `fgr video`.
build_packages=(
    cmake ninja-build g++ pkg-config
    ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers pocl-opencl-icd
    libspdlog-dev libfmt-dev libglm-dev libpng-dev libcli11-dev nlohmann-json3-dev
    libopenexr-dev libstb-dev libtiff-dev zlib1g-dev
    libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
    libsdl2-dev libimgui-dev libgl-dev
)
# And to test it: GoogleTest, Open MPI (optional to build fgr; with it, `mpirun -np N fgr render`
# shares a render between ranks, and the tests run that), Mesa's software rasteriser under the
# virtual X server the viewer tests run in, clinfo and gnuplot for the benchmark scripts,
# clang-format for the style check, jsonschema for the schemas' check, and groff to check the man
# page for warnings.
test_packages=(
    libgtest-dev libopenmpi-dev openmpi-bin libgl1-mesa-dri xvfb xauth clinfo gnuplot-nox
    clang-format python3-jsonschema groff-base
)

# install_missing_packages PACKAGE...: apt-get installs those not installed yet.
install_missing_packages() {
    local missing=()
    for package in "$@"; do
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
    cmake -S "$repo" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFGR_BUILD_TESTS=ON "$@"
    cmake --build "$dir" -j "$jobs"
}

command=${1:-render}
case "$command" in
    render)
        install_missing_packages "${build_packages[@]}"
        # Only fgr and its scenes, configured without the tests, whose packages (GoogleTest)
        # only the test commands install; they turn the tests back on in the same tree.
        cmake -S "$repo" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFGR_WERROR=OFF \
            -DFGR_BUILD_TESTS=OFF
        cmake --build "$build_dir" -j "$jobs" --target fgr fgr_scenes
        "$build_dir/bin/fgr" render mandelbulb -o "${2:-mandelbulb.png}"
        ;;
    test)
        install_missing_packages "${build_packages[@]}" "${test_packages[@]}"
        # CI's build: any compiler warning fails it.
        build "$build_dir" -DFGR_WERROR=ON
        # Two tests at a time keep a 2-core machine busy (each a process running a group of cases:
        # tests/CMakeLists.txt).
        ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" -LE "slow|golden"
        ;;
    test-slow)
        install_missing_packages "${build_packages[@]}" "${test_packages[@]}"
        build "$build_dir" -DFGR_WERROR=ON
        ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" -L slow
        ;;
    test-golden)
        install_missing_packages "${build_packages[@]}" "${test_packages[@]}"
        build "$build_dir" -DFGR_WERROR=ON
        # The golden tier and the slice of it in the slow tier: every case.
        ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" -R "GoldenSet"
        ;;
    test-sanitize)
        install_missing_packages "${build_packages[@]}" "${test_packages[@]}"
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
        echo "usage: ./build.sh [render [OUT.png] | test | test-slow | test-golden | test-sanitize]" >&2
        exit 2
        ;;
esac
