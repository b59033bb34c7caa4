#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The new-user path, as a user would walk it (ctest runs it; so does CI):
#   1. install fgr into a temporary prefix,
#   2. `fgr new-scene` a scene outside any source tree and build it against that prefix only
#      (with the template's warnings on, and none allowed; the build runs `fgr check` on it, and a
#      typo in its .cl fails the build naming the .cl's file and line),
#   3. drop the .so into a plugin folder (FGR_PLUGIN_PATH), then install it into
#      ~/.local/share/fgr/plugins with the install-scene target, and on every build with
#      FGR_INSTALL_SCENE_AFTER_BUILD (a plugin whose kernel does not compile is never installed),
#   4. see it in `fgr list` and render it,
#   5. do the same for every example in sdk/examples.
#
#   tests/sdk_end_to_end.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$(realpath "$1")
source_dir=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "sdk_end_to_end: FAILED: $*" >&2; exit 1; }
step() { echo "== $*"; }

prefix=$work/prefix
# A fresh home (no user plugins, a home to install into) and a kernel cache of its own; the
# drivers' caches where the caller put them (ctest: the build tree's test-cache), else in $work.
export XDG_CACHE_HOME=${XDG_CACHE_HOME:-$work/cache}
export POCL_CACHE_DIR=${POCL_CACHE_DIR:-$XDG_CACHE_HOME/pocl}
export FGR_CACHE_DIR=$work/kernels
export HOME=$work/home
mkdir -p "$HOME"
unset FGR_PLUGIN_PATH

step "install into $prefix"
cmake --install "$build_dir" --prefix "$prefix" > "$work/install.log"
fgr=$prefix/bin/fgr
# The libdir GNUInstallDirs chose (lib, or Debian's lib/x86_64-linux-gnu under the prefix /usr).
libdir=$(sed -n 's/^CMAKE_INSTALL_LIBDIR:[A-Z]*=//p' "$build_dir/CMakeCache.txt")
for file in bin/fgr include/fgr/plugin.h include/fgr/scene_helpers.h \
            "$libdir/cmake/fgr/fgrConfig.cmake" "$libdir/cmake/fgr/FgrScenePlugin.cmake" \
            share/fgr/kernels/fgr_sdf.cl share/fgr/sdk/README.md; do
    [[ -e $prefix/$file ]] || fail "install is missing $file"
done
ls "$prefix"/lib*/fgr/plugins/mandelbulb.so > /dev/null 2>&1 || find "$prefix" -name mandelbulb.so | grep -q . ||
    fail "install is missing the built-in plugins"

step "the installed fgr finds its own plugins"
"$fgr" list > "$work/list.txt"
grep -q "^mandelbulb " "$work/list.txt" || fail "installed fgr does not list mandelbulb"

step "fgr new-scene my-kifs"
cd "$work"
"$fgr" new-scene my-kifs > "$work/new-scene.txt"
for file in CMakeLists.txt my_kifs.c my_kifs.cl README.md; do
    [[ -f my-kifs/$file ]] || fail "new-scene did not write $file"
done
! grep -rq "@SCENE_\|@FGR_PREFIX@" my-kifs || fail "unfilled placeholders in the new project"

step "build it against the prefix, with the exact commands the README gives"
cmake -S my-kifs -B my-kifs/build > "$work/configure.log" || { cat "$work/configure.log"; fail "configure"; }
cmake --build my-kifs/build > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "build"; }
! grep -q "warning:" "$work/build.log" || { cat "$work/build.log"; fail "the template builds with warnings"; }
[[ -f my-kifs/build/my-kifs.so ]] || fail "no my-kifs.so"
if grep -q "$source_dir" my-kifs/build/CMakeCache.txt; then
    fail "the scene's build refers to the engine's source tree"
fi

grep -q "Checking scene my-kifs" "$work/build.log" || { cat "$work/build.log"; fail "the build did not run fgr check"; }
grep -q "my-kifs: all .* checks passed" "$work/build.log" || { cat "$work/build.log"; fail "fgr check did not pass the template"; }

step "a typo in the .cl fails cmake --build with the .cl's file and line"
cp my-kifs/my_kifs.cl "$work/my_kifs.cl.good"
typo_line=$(( $(wc -l < my-kifs/my_kifs.cl) + 2 ))
printf '\nreal typo_here(vec3 p) { return undeclared_name; }\n' >> my-kifs/my_kifs.cl
if cmake --build my-kifs/build > "$work/typo.log" 2>&1; then
    cat "$work/typo.log"; fail "a .cl with a typo built"
fi
grep -q "my_kifs.cl:$typo_line:" "$work/typo.log" || { cat "$work/typo.log"; fail "the build error does not name my_kifs.cl:$typo_line"; }
step "the same with -DFGR_CHECK_SCENE=OFF (the kernel is still compiled), then fixed: builds again"
cmake -S my-kifs -B my-kifs/build -DFGR_CHECK_SCENE=OFF > /dev/null
if cmake --build my-kifs/build > "$work/typo2.log" 2>&1; then
    cat "$work/typo2.log"; fail "a .cl with a typo built with FGR_CHECK_SCENE=OFF"
fi
grep -q "my_kifs.cl:$typo_line:" "$work/typo2.log" || { cat "$work/typo2.log"; fail "no my_kifs.cl:$typo_line with FGR_CHECK_SCENE=OFF"; }
cp "$work/my_kifs.cl.good" my-kifs/my_kifs.cl
cmake -S my-kifs -B my-kifs/build -DFGR_CHECK_SCENE=ON > /dev/null
cmake --build my-kifs/build > "$work/build2.log" 2>&1 || { cat "$work/build2.log"; fail "the fixed .cl does not build"; }

step "drop it into FGR_PLUGIN_PATH: listed and rendered"
mkdir -p plugins && cp my-kifs/build/my-kifs.so plugins/
FGR_PLUGIN_PATH=$work/plugins "$fgr" list > "$work/list2.txt"
grep -q "^my-kifs " "$work/list2.txt" || fail "my-kifs not listed from FGR_PLUGIN_PATH"
FGR_PLUGIN_PATH=$work/plugins "$fgr" render my-kifs -o my-kifs.png --width 96 --height 72 > "$work/render.txt"
hits=$(awk '/^hits /{print $2}' "$work/render.txt")
[[ -f my-kifs.png && ${hits:-0} -gt 500 ]] || fail "my-kifs rendered no surface (hits ${hits:-none})"

step "cmake --build --target install-scene: into ~/.local/share/fgr/plugins, listed"
rm plugins/my-kifs.so
user_plugins=$HOME/.local/share/fgr/plugins
cmake --build my-kifs/build --target install-scene > "$work/install.log" 2>&1 ||
    { cat "$work/install.log"; fail "install-scene"; }
cmp -s my-kifs/build/my-kifs.so "$user_plugins/my-kifs.so" ||
    { cat "$work/install.log"; fail "install-scene did not copy my-kifs.so into $user_plugins"; }
[[ $(ls -A "$user_plugins") == my-kifs.so ]] || fail "install-scene left $(ls -A "$user_plugins")"
"$fgr" list > "$work/list3.txt"
grep -q "^my-kifs " "$work/list3.txt" || fail "my-kifs not listed from ~/.local/share/fgr/plugins"

step "FGR_INSTALL_SCENE_AFTER_BUILD: every build installs; a kernel that does not compile is not installed"
cmake -S my-kifs -B my-kifs/build -DFGR_INSTALL_SCENE_AFTER_BUILD=ON -DFGR_CHECK_SCENE=OFF > /dev/null
printf '\n/* edited */\n' >> my-kifs/my_kifs.cl
cmake --build my-kifs/build > "$work/after.log" 2>&1 || { cat "$work/after.log"; fail "build"; }
cmp -s my-kifs/build/my-kifs.so "$user_plugins/my-kifs.so" ||
    { cat "$work/after.log"; fail "the build did not install the rebuilt my-kifs.so"; }
cp "$user_plugins/my-kifs.so" "$work/installed.so"
printf '\nreal typo_here(vec3 p) { return undeclared_name; }\n' >> my-kifs/my_kifs.cl
# install-scene itself: it must wait for the kernel's check, whatever order the build takes.
if cmake --build my-kifs/build --target install-scene > "$work/after-typo.log" 2>&1; then
    cat "$work/after-typo.log"; fail "install-scene of a .cl with a typo succeeded"
fi
cmp -s "$work/installed.so" "$user_plugins/my-kifs.so" || fail "a plugin that does not compile was installed"
cp "$work/my_kifs.cl.good" my-kifs/my_kifs.cl
cmake -S my-kifs -B my-kifs/build -DFGR_INSTALL_SCENE_AFTER_BUILD=OFF -DFGR_CHECK_SCENE=ON > /dev/null

for example in "$source_dir"/sdk/examples/*/; do
    name=$(basename "$example")
    step "example $name: copy out, build against the prefix, render"
    cp -r "$example" "$work/$name"
    cmake -S "$work/$name" -B "$work/$name/build" -DCMAKE_PREFIX_PATH="$prefix" > "$work/$name.log" ||
        { cat "$work/$name.log"; fail "configure $name"; }
    cmake --build "$work/$name/build" >> "$work/$name.log" 2>&1 || { cat "$work/$name.log"; fail "build $name"; }
    ! grep -q "warning:" "$work/$name.log" || { cat "$work/$name.log"; fail "$name builds with warnings"; }
    grep -q "$name: all .* checks passed" "$work/$name.log" || { cat "$work/$name.log"; fail "fgr check did not pass $name"; }
    mkdir -p "$work/examples" && cp "$work/$name"/build/*.so "$work/examples/"
    FGR_PLUGIN_PATH=$work/examples "$fgr" render "$name" -o "$name.png" --width 96 --height 72 > "$work/$name.txt"
    hits=$(awk '/^hits /{print $2}' "$work/$name.txt")
    [[ ${hits:-0} -gt 500 ]] || fail "$name rendered no surface (hits ${hits:-none})"
done
echo "sdk_end_to_end: the new-user path works"
