#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Sets up, builds and runs fgr on Debian 12. The two commands the README gives:
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
#   ./build.sh docs            the documentation site (mkdocs.yml) into BUILD_DIR/site, from the
#                              pages in docs/ and the CLI reference fgr generates; any broken link
#                              fails it
#   ./build.sh package         the Debian packages fgr, fgr-viewer, fgr-video, fgr-mpi and fgr-sdk
#                              from the build tree (built first where needed), into build/packages
#                              (docs/packages.md)
#   ./build.sh prepare-clean-root DIR
#                              a clean Debian 12 root in DIR (mmdebstrap) with the runtime
#                              libraries fgr's packages depend on: what test-package installs into
#   ./build.sh test-package [DIR]
#                              the packages, installed with apt into the prepared root DIR (else a
#                              root made now) and run there (tests/package/); removes DIR after
#   ./build.sh remove-clean-root DIR
#                              removes a prepared root (refused while anything is mounted in it)
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
# page for warnings, and zsh to check its completion script.
test_packages=(
    libgtest-dev libopenmpi-dev openmpi-bin libgl1-mesa-dri xvfb xauth clinfo gnuplot-nox
    clang-format python3-jsonschema groff-base zsh
)
# And to build the documentation site: MkDocs (Debian 12 has 1.4, with its themes).
docs_packages=(mkdocs)

# And to make the Debian packages: dpkg-shlibdeps (dpkg-dev, which needs `file`) derives their
# Depends; mmdebstrap makes the clean root the packages are tested in.
package_packages=(dpkg-dev file)
clean_root_packages_tools=(mmdebstrap)
# What the clean root is prepared with, so that test-package only installs fgr's .deb files: the
# runtime libraries fgr's packages depend on and what building a scene with fgr-sdk needs. The test
# fails when the packages' Depends do not ask for every one of them (apt-get autoremove), so this
# list and the Depends stay in step; one missing here is only fetched during the test.
clean_root_packages=(
    ocl-icd-libopencl1 pocl-opencl-icd libspdlog1.10 libfmt9 libpng16-16 libtiff6 zlib1g
    libopenexr-3-1-30 libstb0 cmake make gcc libc6-dev
)
# And what a user's system has that the test uses to read the man page and complete a command
# line; installed as wanted (not as dependencies), so the autoremove check leaves them alone.
clean_root_tools=(man-db bash-completion)
debian_mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
debian_security_mirror=${DEBIAN_SECURITY_MIRROR:-http://deb.debian.org/debian-security}

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
    cmake -S "$repo" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFGR_BUILD_TESTS=ON \
        "${prefix_option[@]}" "$@"
    cmake --build "$dir" -j "$jobs"
}
# The build tree is configured for the prefix the Debian packages install into, so GNUInstallDirs
# picks Debian's multiarch libdir (lib/x86_64-linux-gnu) for the tree and the packages alike; fgr
# finds its files relative to its binary, so `cmake --install build --prefix PREFIX` works as well.
prefix_option=(-DCMAKE_INSTALL_PREFIX=/usr)

# make_packages: the Debian packages from the build tree into $build_dir/packages. A tree built
# already (./build.sh test) is packed as it is; a fresh one is configured without the tests first.
make_packages() {
    install_missing_packages "${build_packages[@]}" "${package_packages[@]}"
    if [[ ! -f $build_dir/CMakeCache.txt ]]; then
        cmake -S "$repo" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFGR_BUILD_TESTS=OFF \
            "${prefix_option[@]}"
    fi
    cmake --build "$build_dir" -j "$jobs"
    rm -rf "$build_dir/packages"
    (cd "$build_dir" && cpack -G DEB -B "$build_dir/packages" > "$build_dir/cpack.log") ||
        { cat "$build_dir/cpack.log" >&2; exit 1; }
    rm -rf "$build_dir/packages/_CPack_Packages"
    ls "$build_dir/packages"/*.deb
}

# prepare_clean_root DIR: a Debian 12 root in DIR (which must not exist or be empty) with apt, the
# archive's lists and clean_root_packages, those marked as installed automatically (test-package's
# autoremove check).
prepare_clean_root() {
    local dir=$1
    install_missing_packages "${clean_root_packages_tools[@]}"
    mmdebstrap --mode=root --variant=apt --skip=cleanup/apt/lists \
        --include="$(IFS=,; echo "${clean_root_packages[*]}" "${clean_root_tools[*]}" | tr ' ' ,)" \
        --customize-hook="chroot \"\$1\" apt-mark auto ${clean_root_packages[*]} > /dev/null" \
        bookworm "$dir" \
        "deb $debian_mirror bookworm main" "deb $debian_mirror bookworm-updates main" \
        "deb $debian_security_mirror bookworm-security main"
}

# remove_root DIR: removes a root made by prepare_clean_root, refusing while anything is mounted
# in it (the test mounts /proc only inside a private mount namespace).
remove_root() {
    local dir
    dir=$(realpath -m "$1")
    [[ -d $dir ]] || return 0
    if findmnt -rn -o TARGET | grep -q "^$dir/"; then
        echo "build.sh: something is still mounted in $dir; not removing it" >&2
        return 1
    fi
    rm -rf --one-file-system "$dir"
}

command=${1:-render}
case "$command" in
    render)
        install_missing_packages "${build_packages[@]}"
        # Only fgr and its scenes, configured without the tests, whose packages (GoogleTest)
        # only the test commands install; they turn the tests back on in the same tree.
        cmake -S "$repo" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFGR_WERROR=OFF \
            -DFGR_BUILD_TESTS=OFF "${prefix_option[@]}"
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
        # Once; only a test that failed with LeakSanitizer's own tracer crash runs again, and
        # each rerun is listed (tests/sanitized_ctest.sh).
        "$repo/tests/sanitized_ctest.sh" "$sanitize_build_dir" "$jobs"
        ;;
    docs)
        install_missing_packages "${build_packages[@]}" "${docs_packages[@]}"
        # The CLI reference comes from fgr itself (the target fgr_generated_docs); a tree the test
        # commands configured is reused as it is, a fresh one is configured as render does.
        if [[ ! -f $build_dir/CMakeCache.txt ]]; then
            cmake -S "$repo" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFGR_WERROR=OFF \
                -DFGR_BUILD_TESTS=OFF
        fi
        cmake --build "$build_dir" -j "$jobs" --target fgr_generated_docs
        python3 "$repo/docs/stage.py" "$repo" "$build_dir/docs-src" \
            --cli-reference "$build_dir/docs/cli-reference.md"
        FGR_DOCS_STAGED="$build_dir/docs-src" FGR_SITE_DIR="$build_dir/site" \
            mkdocs build --strict --config-file "$repo/mkdocs.yml"
        echo "build.sh: the site is in $build_dir/site (open index.html)"
        ;;
    package)
        make_packages
        ;;
    prepare-clean-root)
        [[ $# -eq 2 ]] || { echo "usage: ./build.sh prepare-clean-root DIR" >&2; exit 2; }
        prepare_clean_root "$2"
        ;;
    remove-clean-root)
        [[ $# -eq 2 ]] || { echo "usage: ./build.sh remove-clean-root DIR" >&2; exit 2; }
        remove_root "$2"
        ;;
    test-package)
        install_missing_packages "${clean_root_packages_tools[@]}"
        make_packages
        if [[ $# -ge 2 ]]; then
            root=$2
        else
            root=$(mktemp -d /tmp/fgr-clean-root.XXXXXX)
            rmdir "$root"
            trap 'remove_root "$root"' EXIT
            prepare_clean_root "$root"
        fi
        trap 'remove_root "$root"' EXIT
        "$repo/tests/package/install_in_clean_root.sh" "$build_dir/packages" "$root" "$build_dir"
        ;;
    *)
        echo "usage: ./build.sh [render [OUT.png] | test | test-slow | test-golden | test-sanitize |" \
            "docs | package | prepare-clean-root DIR | test-package [DIR]]" >&2
        exit 2
        ;;
esac
