#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Packs a built fgr into one folder that runs on another x86-64 Linux machine with nothing
# installed: fgr, its scene plugins, the test executable, every shared library they need (the
# OpenCL ICD loader libOpenCL.so.1 included) and glibc with its loader, so the kit also runs where
# the system's glibc is older than the build machine's. run.sh (copied in) runs it there.
#
#   bench/gpu/pack.sh [BUILD_DIR [KIT_DIR]]     (default: build-gpu, .gpu-kit, both in this repo)
#
# KIT_DIR is emptied first. When it lies in a git checkout, its folder is added to that checkout's
# .git/info/exclude, so the kit travels as an ignored folder (e.g. the device tool's `carry`).
#
# Layout (the build tree's, so fgr finds its plugins at bin/../lib/fgr/plugins):
#   bin/fgr, bin/fgr_tests        the executables as built
#   bin/ld-linux-x86-64.so.2      glibc's loader, beside them: started through it, /proc/self/exe
#                                 is the loader, whose folder is fgr's, so plugins are found alike
#   lib/                          every library ldd names but glibc's; lib/fgr/plugins the scenes
#   glibc/                        libc, libm, libdl, libpthread, librt, libresolv of the build machine
#   run.sh                        the device script
#   kit.env                       what was packed: commit, build type, the test paths built in
#                                 (the plugin folder, fgr, the drivers' cache)
#
# The build must be headless (no viewer, video or MPI), so neither fgr_tests nor anything else in
# the kit needs FFmpeg, SDL2, OpenGL or MPI: configure it as
#   cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release -DFGR_BUILD_VIEWER=OFF \
#       -DFGR_BUILD_VIDEO=OFF -DFGR_MPI=OFF -DFGR_BUILD_TESTS=ON
# pack.sh refuses another build, and a packed object that names one of those libraries.
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
build=$(cd "${1:-$repo/build-gpu}" && pwd)
kit=${2:-$repo/.gpu-kit}

fgr=$build/bin/fgr
tests=$build/bin/fgr_tests
plugins=$build/lib/fgr/plugins
for needed in "$fgr" "$tests" "$plugins"; do
    [[ -e $needed ]] || { echo "pack: $needed is missing; build fgr fgr_scenes fgr_tests first" >&2; exit 1; }
done
cache=$build/CMakeCache.txt
for option in FGR_BUILD_VIEWER FGR_BUILD_VIDEO FGR_MPI; do
    if [[ $(sed -n "s/^$option:[A-Z]*=//p" "$cache") != OFF ]]; then
        echo "pack: $build is not headless ($option is not OFF); configure it with" \
            "-DFGR_BUILD_VIEWER=OFF -DFGR_BUILD_VIDEO=OFF -DFGR_MPI=OFF" >&2
        exit 1
    fi
done

# What a headless build never needs: a packed object that names one was built with them.
unwanted='^lib(avcodec|avformat|avutil|swscale|swresample|avfilter|avdevice|postproc|SDL2-2\.0|GL|OpenGL|GLX|EGL|mpi[a-z_]*)\.so'
glibc_names=(libc.so.6 libm.so.6 libdl.so.2 libpthread.so.0 librt.so.1 libresolv.so.2)

rm -rf "$kit"
mkdir -p "$kit/bin" "$kit/lib/fgr" "$kit/glibc"
cp "$fgr" "$tests" "$kit/bin/"
cp -r "$plugins" "$kit/lib/fgr/plugins"
cp "$script_dir/run.sh" "$kit/run.sh"

is_glibc() {
    local name=$1 g
    [[ $name == ld-linux-x86-64.so.2 ]] && return 0
    for g in "${glibc_names[@]}"; do [[ $name == "$g" ]] && return 0; done
    return 1
}

# The libraries a file needs, by path, through its whole closure (ldd).
declare -A shipped=()
add_closure_of() {
    local object=$1 name path
    while read -r name path; do
        [[ -n $path && -e $path ]] || continue
        shipped[$name]=$path
    done < <(ldd "$object" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }')
}
for object in "$fgr" "$tests" "$plugins"/*.so; do
    mapfile -t needs < <(readelf -d "$object" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
    declare -A where=()
    while read -r name path; do where[$name]=$path; done \
        < <(ldd "$object" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }')
    for name in "${needs[@]}"; do
        if [[ $name =~ $unwanted ]]; then
            echo "pack: $object needs $name: the build is not headless" >&2
            exit 1
        fi
        path=${where[$name]:-}
        [[ -n $path ]] || continue  # the loader itself
        shipped[$name]=$path
        add_closure_of "$path"
    done
    unset where
done

for name in "${!shipped[@]}"; do
    if is_glibc "$name"; then
        cp -L "${shipped[$name]}" "$kit/glibc/$name"
    else
        cp -L "${shipped[$name]}" "$kit/lib/$name"
    fi
done
# All of glibc's common libraries, named by the object or not: the NVIDIA driver's libraries,
# loaded at run time, need libdl, libpthread and librt, which must come from the same glibc.
libdir=$(dirname "$(ldd "$fgr" | awk '$1 == "libc.so.6" { print $3 }')")
for name in "${glibc_names[@]}"; do
    [[ -e $kit/glibc/$name ]] || cp -L "$libdir/$name" "$kit/glibc/$name"
done
loader=$(ldd "$fgr" | awk '/ld-linux-x86-64\.so\.2/ { print ($3 ~ /^\//) ? $3 : $1 }' | head -n 1)
cp -L "$loader" "$kit/bin/ld-linux-x86-64.so.2"

{
    echo "# written by bench/gpu/pack.sh"
    echo "packed_at=$(date -u +%Y-%m-%dT%H:%M:%SZ)"
    echo "commit=$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
    echo "build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$cache")"
    echo "glibc=$(ldd --version | head -n 1 | awk '{ print $NF }')"
    # Paths compiled into fgr_tests: run.sh links them to the kit where they do not exist.
    echo "test_plugin_dir=$plugins"
    echo "test_fgr_exe=$fgr"
    echo "test_driver_cache=$(sed -n 's/^FGR_TEST_DRIVER_CACHE:[A-Z]*=//p' "$cache")"
} > "$kit/kit.env"

# Ignored by the checkout the kit lies in.
if top=$(git -C "$(dirname "$kit")" rev-parse --show-toplevel 2>/dev/null); then
    common=$(git -C "$top" rev-parse --path-format=absolute --git-common-dir)
    relative=$(realpath --relative-to="$top" "$kit")
    if [[ $relative != ..* ]] && ! grep -qxF "/$relative/" "$common/info/exclude" 2>/dev/null; then
        mkdir -p "$common/info"
        echo "/$relative/" >> "$common/info/exclude"
    fi
fi

echo "packed $(du -sh "$kit" | cut -f1) into $kit: $(ls "$kit/lib" | wc -l) libraries" \
    "(libOpenCL.so.1 among them), glibc $(ls "$kit/glibc" | wc -l)"
