#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# install_in_clean_root.sh PACKAGE_DIR ROOT [BUILD_DIR]: fgr's Debian packages, installed into a
# clean Debian 12 root as a user's machine would get them.
#
# PACKAGE_DIR holds the .deb files `./build.sh package` made; ROOT is a Debian 12 root that
# `./build.sh prepare-clean-root ROOT` made (mmdebstrap: apt, the archive's lists, and the runtime
# libraries fgr's packages depend on, marked as installed automatically). BUILD_DIR, when given,
# is the tree the packages were made from: where it made the man page, the package must carry it.
#
# Checks, each failing with one line saying what is wrong:
#   - every package is there; no Depends names a -dev package; fgr depends on an OpenCL driver,
#     the others on fgr of the same version; each carries /usr/share/doc/PACKAGE/copyright naming
#     the Apache License 2.0 where Debian keeps it
#   - apt installs fgr and fgr-sdk from the .deb files, resolving their Depends from the archive;
#     then nothing in the root is left that no installed package needs (apt-get autoremove): the
#     runtime libraries the root was prepared with are what the packages' Depends ask for, so a
#     Depends missing from a package shows here
#   - apt resolves fgr-viewer, fgr-video and fgr-mpi too (--simulate: nothing downloaded)
#   - inside the root: `fgr list` lists mandelbulb, `fgr render mandelbulb` writes a PNG that is not
#     a blank image, `man fgr` shows the page, bash-completion loads fgr's script and completes a
#     scene id, `fgr new-scene` + cmake build a scene out of tree against the installed fgr-sdk
#     (find_package(fgr)), and fgr renders it by path
#
# Runs as root (chroot). The chroot gets /proc, /sys and /dev/shm in a private mount namespace,
# gone when each command ends, so nothing stays mounted in ROOT.
set -euo pipefail
package_dir=$(cd "$1" && pwd)
root=$(cd "$2" && pwd)
build_dir=${3:-}

fail() {
    echo "install_in_clean_root: FAILED: $*" >&2
    exit 1
}
step() { echo "== [${SECONDS} s] $*"; }

# in_root COMMAND...: runs COMMAND in ROOT as root, with a plain environment and /proc, /sys and
# /dev/shm mounted (fgr finds its files from /proc/self/exe; PoCL reads the CPU's topology and
# memory from /proc and /sys), all in a mount namespace of its own that ends with COMMAND.
in_root() {
    unshare --mount --propagation private --pid --fork --mount-proc="$root/proc" \
        sh -ec 'mount -t sysfs -o ro sysfs "$0/sys"; mount -t tmpfs tmpfs "$0/dev/shm"
            exec chroot "$0" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin \
                LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"' "$root" "$@"
}

[[ -x $root/usr/bin/apt-get ]] || fail "$root is not a prepared root (./build.sh prepare-clean-root)"

step "the packages and their control fields"
declare -A deb
for package in fgr fgr-viewer fgr-video fgr-mpi fgr-sdk; do
    files=("$package_dir/${package}_"*.deb)
    [[ -f ${files[0]} ]] || fail "no ${package}_*.deb in $package_dir"
    [[ ${#files[@]} -eq 1 ]] || fail "more than one ${package}_*.deb in $package_dir: ${files[*]}"
    deb[$package]=${files[0]}
done
version=$(dpkg-deb -f "${deb[fgr]}" Version)
for package in "${!deb[@]}"; do
    depends=$(dpkg-deb -f "${deb[$package]}" Depends)
    echo "$package $version: Depends: $depends"
    # Each alternative's name, one a line.
    names=$(tr ',|' '\n\n' <<<"$depends" | sed -E 's/\(.*\)//; s/^ +//; s/ +$//' | grep -v '^$' || true)
    if grep -E -- '-dev$' <<<"$names"; then
        fail "$package depends on a -dev package (what building needs, not running)"
    fi
    if [[ $package != fgr ]]; then
        grep -qF "fgr (= $version)" <<<"$depends" || fail "$package does not depend on fgr (= $version)"
    fi
    contents=$(dpkg-deb -c "${deb[$package]}")
    grep -q " ./usr/share/doc/$package/copyright$" <<<"$contents" ||
        fail "$package has no /usr/share/doc/$package/copyright"
    copyright=$(dpkg-deb --fsys-tarfile "${deb[$package]}" | tar -xO "./usr/share/doc/$package/copyright")
    grep -q "/usr/share/common-licenses/Apache-2.0" <<<"$copyright" ||
        fail "$package's copyright does not point at /usr/share/common-licenses/Apache-2.0"
done
fgr_depends=$(dpkg-deb -f "${deb[fgr]}" Depends)
grep -q "ocl-icd-libopencl1" <<<"$fgr_depends" || fail "fgr does not depend on the OpenCL ICD loader"
grep -qF "pocl-opencl-icd | opencl-icd" <<<"$fgr_depends" || fail "fgr does not depend on an OpenCL driver"
sdk_depends=$(dpkg-deb -f "${deb[fgr-sdk]}" Depends)
for needed in cmake gcc; do
    grep -qw "$needed" <<<"$sdk_depends" || fail "fgr-sdk does not depend on $needed"
done
fgr_contents=$(dpkg-deb -c "${deb[fgr]}")
for doc in LICENSE NOTICE third-party-licences.md; do
    grep -q " ./usr/share/doc/fgr/$doc$" <<<"$fgr_contents" || fail "fgr does not carry $doc"
done
if [[ -n $build_dir && -f $build_dir/share/man/man1/fgr.1 ]]; then
    grep -q " ./usr/share/man/man1/fgr.1.gz$" <<<"$fgr_contents" ||
        fail "fgr does not carry /usr/share/man/man1/fgr.1.gz"
fi

step "apt-get install fgr fgr-sdk into the clean root"
mkdir -p "$root/tmp/fgr-debs"
cp "${deb[@]}" "$root/tmp/fgr-debs/"
in_root apt-get install -y -q --no-install-recommends \
    "/tmp/fgr-debs/$(basename "${deb[fgr]}")" "/tmp/fgr-debs/$(basename "${deb[fgr-sdk]}")" \
    > "$root/tmp/install.log" 2>&1 || { cat "$root/tmp/install.log"; fail "apt-get install fgr fgr-sdk"; }
grep -E "^(Setting up|The following NEW)" "$root/tmp/install.log" | head -20 || true

step "nothing the packages do not depend on is left over"
removable=$(in_root apt-get autoremove --simulate | awk '/^Remv /{print $2}')
[[ -z $removable ]] || fail "installed, yet no package depends on them: $(echo $removable) (a" \
    "Depends missing from fgr's packages, or build.sh's clean_root_packages names more than they need)"

step "apt resolves fgr-viewer, fgr-video, fgr-mpi"
for package in fgr-viewer fgr-video fgr-mpi; do
    in_root apt-get install --simulate -q "/tmp/fgr-debs/$(basename "${deb[$package]}")" \
        > "$root/tmp/simulate.log" 2>&1 || { cat "$root/tmp/simulate.log"; fail "apt cannot install $package"; }
done

step "fgr list, fgr render mandelbulb"
in_root fgr list > "$root/tmp/list.txt" 2>&1 || { cat "$root/tmp/list.txt"; fail "fgr list"; }
grep -qw mandelbulb "$root/tmp/list.txt" || { cat "$root/tmp/list.txt"; fail "fgr list does not list mandelbulb"; }
in_root sh -c 'cd /tmp && fgr render mandelbulb -o mandelbulb.png' \
    > "$root/tmp/render.txt" 2>&1 || { cat "$root/tmp/render.txt"; fail "fgr render mandelbulb"; }
png=$root/tmp/mandelbulb.png
[[ -f $png ]] || fail "fgr render wrote no mandelbulb.png"
# A blank 640x480 image compresses to a few kilobytes; the Mandelbulb takes a hundred or more.
size=$(stat -c %s "$png")
((size > 20000)) || fail "mandelbulb.png is $size bytes: a blank image?"
echo "mandelbulb.png: $size bytes"

step "man fgr, and bash completing a scene id"
# The root has man-db and bash-completion as a user's system would (build.sh's clean_root_tools).
in_root sh -c 'MANPAGER=cat MANWIDTH=100 man fgr' > "$root/tmp/man.txt" 2> "$root/tmp/man-errors.txt" ||
    { cat "$root/tmp/man-errors.txt"; fail "man fgr"; }
for section in NAME SYNOPSIS COMMANDS; do
    grep -q "^$section" "$root/tmp/man.txt" || fail "man fgr has no $section section"
done
grep -q "fgr render" "$root/tmp/man.txt" || fail "man fgr does not describe fgr render"
# bash-completion finds fgr's script where the package put it, on first use, as an
# interactive shell would; the function it registers completes a scene id from `fgr list --ids`.
in_root bash -c 'source /usr/share/bash-completion/bash_completion
    __load_completion fgr || exit 3
    function=$(complete -p fgr | sed -E "s/.* -F ([^ ]+) .*/\1/")
    COMP_WORDS=(fgr render mandel); COMP_CWORD=2; COMP_LINE="fgr render mandel"
    COMP_POINT=${#COMP_LINE}
    "$function" fgr mandel render
    printf "%s\n" "${COMPREPLY[@]}"' > "$root/tmp/completion.txt" 2>&1 ||
    { cat "$root/tmp/completion.txt"; fail "bash-completion does not load fgr's completion"; }
grep -qx mandelbulb "$root/tmp/completion.txt" ||
    { cat "$root/tmp/completion.txt"; fail "bash does not complete 'fgr render mandel' to mandelbulb"; }

step "a scene built against the installed fgr-sdk, rendered by path"
in_root sh -ec 'cd /tmp && fgr new-scene my-scene > /dev/null &&
    cmake -S my-scene -B my-scene/build > configure.log &&
    cmake --build my-scene/build > build.log 2>&1 &&
    fgr render my-scene/build/my-scene.so -o my-scene.png --width 96 --height 72 > render.log' ||
    { cat "$root"/tmp/{configure,build,render}.log 2>/dev/null; fail "building or rendering the SDK's template scene"; }
[[ -s $root/tmp/my-scene.png ]] || fail "the template scene rendered no my-scene.png"
grep -q "/usr/lib/.*cmake/fgr" "$root/tmp/my-scene/build/CMakeCache.txt" ||
    fail "the scene's build did not find the installed fgr-sdk's CMake package"

echo "install_in_clean_root: all checks passed in ${SECONDS} s"
