#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# fgr's GPU checks, run from a kit that bench/gpu/pack.sh made of a headless build (pack.sh copies
# this script into it). It finds the NVIDIA OpenCL driver, writes an ICD file naming its
# libnvidia-opencl.so.1 and points the kit's own ICD loader at it (without the driver, OpenCL's
# own vendors, e.g. PoCL, are used), then runs, each step under a time limit and whatever the last
# one did:
#   fgr info, fgr info --math-check              the devices and the math self-test's verdicts
#   fgr_tests Scenes/LaneSafety.*_float          every scene's lane safety at packet width 1 (the
#                                                layout a GPU renders with), sharded
#   fgr check SCENE                              the numerical stability suite on every plugin
#                                                scene, several at once
#   fgr bench mandelbulb, fgr bench benchmark    1920x1080 in every mode the scene has (shaded,
#                                                path, brute), 5 s each
#   fgr render mandelbulb, shaded and path       1920x1080 PNGs to OUT, to compare with a CPU's
#   narrowing a failed bench                     320x180 renders of that scene and mode at 1, 4
#                                                and 8 rays per work-item (path: and without
#                                                regrouping), to tell a layout's fault from the
#                                                scene's
#
#   bash .gpu-kit/run.sh
#
# Environment: OUT (results; default ./gpu-kit-out), FGR_KIT_BUDGET (seconds for all the steps,
# default 450, inside the 8 minutes the kit is given: a step gets at most its own limit and what
# is left), FGR_KIT_TESTS (the tests' gtest filter), FGR_KIT_SHARDS (test processes at once;
# default half the cores, at most 8), FGR_KIT_QUICK=1 (320x180, 2 s benches, the Mandelbulb's
# tests and check only: to try the kit on a 2-core CPU in a few minutes), FGR_KIT_NARROW (extra
# SCENE/MODE pairs to narrow down as if their bench had failed, e.g. "benchmark/path": to try that
# step where nothing fails).
#
# OUT receives run.log (everything), tests.log, checks.log, the two PNGs and bench.tar.gz (each
# bench's JSON and CSV). Exit status 0 once all steps have run; each step's own is in the summary at
# the end.
set -uo pipefail
export LC_ALL=C

kit=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
OUT=${OUT:-$PWD/gpu-kit-out}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
work=$(mktemp -d /tmp/fgr-kit.XXXXXX)
budget=${FGR_KIT_BUDGET:-450}
quick=${FGR_KIT_QUICK:-0}
exec > >(tee -a "$OUT/run.log") 2>&1
tee_pid=$!

if [[ $quick == 1 ]]; then
    width=320 height=180 duration=2 spp=4
    default_tests='Scenes/LaneSafety.*/mandelbulb_float'
else
    width=1920 height=1080 duration=5 spp=64
    default_tests='Scenes/LaneSafety.*_float'
fi
test_filter=${FGR_KIT_TESTS:-$default_tests}

start=$SECONDS
summary=()
left() { echo $((budget - (SECONDS - start))); }
note() { summary+=("$(printf '%-40s %s' "$1" "$2")"); }

# step NAME LIMIT COMMAND...: runs COMMAND under min(LIMIT, what is left of the budget).
step() {
    local name=$1 limit=$2
    shift 2
    local remaining
    remaining=$(left)
    if ((remaining < 10)); then
        echo "== $name: skipped, the budget is spent"
        note "$name" "skipped (budget)"
        return 0
    fi
    ((limit > remaining)) && limit=$remaining
    echo
    echo "== $name (limit ${limit} s)"
    echo "\$ ${*//"$kit"\//}"
    local t0=$SECONDS rc
    timeout -k 5 "$limit" "$@"
    rc=$?
    local verdict="exit $rc"
    ((rc == 124 || rc == 137)) && verdict="exit $rc (timed out)"
    echo "== $name: $verdict after $((SECONDS - t0)) s"
    note "$name" "$verdict, $((SECONDS - t0)) s"
    step_rc=$rc
    return 0
}
step_rc=0  # the exit status of the last step that ran (0 for one skipped)

kv() { sed -n "s/^$1=//p" "$kit/kit.env"; }

echo "== fgr GPU kit, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
sed 's/^/kit: /' "$kit/kit.env"
echo "host: $(uname -srm), $(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME"), $(nproc) cores"
echo "system glibc: $(ldd --version 2>/dev/null | head -n 1 | awk '{ print $NF }')"
echo "OUT: $OUT, budget $budget s"

echo
echo "== nvidia-smi"
if command -v nvidia-smi > /dev/null; then
    timeout 30 nvidia-smi
    timeout 30 nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.sm \
        --format=csv
else
    echo "no nvidia-smi on PATH"
fi

echo
echo "== the NVIDIA OpenCL driver"
driver=
for dir in /usr/lib/x86_64-linux-gnu /usr/local/nvidia/lib64 /usr/lib64 /usr/local/nvidia/lib /usr/lib; do
    if [[ -e $dir/libnvidia-opencl.so.1 ]]; then
        echo "found $dir/libnvidia-opencl.so.1 -> $(readlink -f "$dir/libnvidia-opencl.so.1")"
        [[ -z $driver ]] && driver=$dir/libnvidia-opencl.so.1
    fi
done
echo "ldconfig knows: $(ldconfig -p 2>/dev/null | grep -E 'libnvidia-opencl|libcuda\.so' | awk '{ print $NF }' | tr '\n' ' ')"
echo "/etc/OpenCL/vendors: $(cat /etc/OpenCL/vendors/*.icd 2>/dev/null | tr '\n' ' ')"
driver_dir=
if [[ -n $driver ]]; then
    driver_dir=$(dirname "$driver")
    mkdir -p "$work/icd"
    echo "$driver" > "$work/icd/nvidia.icd"
    export OCL_ICD_VENDORS=$work/icd
    echo "using $driver: OCL_ICD_VENDORS=$OCL_ICD_VENDORS (nvidia.icd names it)"
else
    echo "no libnvidia-opencl.so.1: OpenCL's own vendors are used" \
        "(OCL_ICD_VENDORS=${OCL_ICD_VENDORS:-unset}; PoCL where it is installed)"
fi

# Two ways to start the kit's programs: through the kit's own glibc loader (runs on any x86-64
# Linux), else the system's loader with the kit's libraries but the system's glibc.
libpath=$kit/lib:$kit/glibc${driver_dir:+:$driver_dir}
kit_launch=("$kit/bin/ld-linux-x86-64.so.2" --library-path "$libpath")
system_launch=(env "LD_LIBRARY_PATH=$kit/lib${driver_dir:+:$driver_dir}")
if [[ -n $driver ]]; then
    echo "the driver's needs through the kit's loader:"
    timeout 20 "${kit_launch[@]}" --list "$driver" 2>&1 | sed 's/^/  /'
fi

export FGR_CACHE_DIR=$work/cache  # cold: kernel builds are measured, then shared by the steps
launch=()
info=
for mode in kit system; do
    if [[ $mode == kit ]]; then candidate=("${kit_launch[@]}"); else candidate=("${system_launch[@]}"); fi
    echo
    echo "== fgr info through the $mode loader"
    output=$(timeout 60 "${candidate[@]}" "$kit/bin/fgr" info 2>&1)
    rc=$?
    echo "$output"
    echo "== exit $rc"
    note "fgr info ($mode loader)" "exit $rc"
    if ((rc == 0)) && [[ -z $info ]]; then launch=("${candidate[@]}") info=$output; fi
    if ((rc == 0)) && grep -q 'type: *GPU' <<< "$output"; then
        launch=("${candidate[@]}") info=$output
        break
    fi
    [[ -z $driver && -n $info ]] && break  # no GPU to look for
done
if [[ -z $info ]]; then
    launch=("${kit_launch[@]}")
    echo "fgr info failed both ways; the steps run through the kit's loader regardless"
fi
device=$(awk 'tolower($1) == "device" && $2 ~ /^[0-9]+:$/ { d = $2; sub(":", "", d) } /type:/ && /GPU/ { print d; exit }' <<< "$info")
if [[ -z $device ]]; then
    device=0
    echo "no GPU among the devices: the steps run on device 0"
    if [[ -n $driver ]]; then
        echo "== the ICD loader's account (OCL_ICD_DEBUG=15)"
        OCL_ICD_DEBUG=15 timeout 30 "${launch[@]}" "$kit/bin/fgr" info 2>&1 | tail -n 40
    fi
fi
echo "running on device $device through: ${launch[*]//"$kit"\//}"
fgr=("${launch[@]}" "$kit/bin/fgr")
dev=(--device "$device")
size=(--width "$width" --height "$height")

step "info --math-check" 90 "${fgr[@]}" info --math-check

# The tests: paths compiled into fgr_tests (the build's plugin folder, the drivers' cache) are
# linked to the kit where they do not exist.
echo
echo "== fgr_tests: lane safety at packet width 1"
plugin_dir=$(kv test_plugin_dir)
driver_cache=$(kv test_driver_cache)
if [[ ! -e $plugin_dir ]]; then
    if mkdir -p "$(dirname "$plugin_dir")" && ln -s "$kit/lib/fgr/plugins" "$plugin_dir"; then
        echo "linked $plugin_dir -> the kit's plugins"
    else
        echo "cannot make $plugin_dir: the scene-wide tests will find no scenes"
    fi
fi
[[ -n $driver_cache ]] && mkdir -p "$driver_cache" 2>/dev/null
cores=$(nproc)
shards=${FGR_KIT_SHARDS:-$((cores / 2 > 8 ? 8 : (cores / 2 < 1 ? 1 : cores / 2)))}
echo "filter: $test_filter; FGR_TEST_PACKET_WIDTHS=1"
echo "$shards shards at once; the tests open the first GPU, else the first device (open_device(-1))"
tests=("${launch[@]}" "$kit/bin/fgr_tests")
remaining=$(left)
test_limit=$((quick == 1 ? 240 : 180))
((test_limit > remaining - 5)) && test_limit=$((remaining - 5))
if ((test_limit < 15)); then
    echo "== fgr_tests: skipped, the budget is spent"
    note "lane safety, width 1" "skipped (budget)"
else
    t0=$SECONDS
    echo "== fgr_tests (limit $test_limit s)"
    pids=()
    for ((shard = 0; shard < shards; ++shard)); do
        FGR_TEST_PACKET_WIDTHS=1 GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard \
            timeout -k 5 "$test_limit" "${tests[@]}" --gtest_filter="$test_filter" \
            > "$work/tests-$shard.log" 2>&1 &
        pids+=($!)
    done
    worst=0
    for ((shard = 0; shard < shards; ++shard)); do
        wait "${pids[$shard]}"
        rc=$?
        echo "shard $shard: exit $rc, $(grep -E '^\[  PASSED  \]|^\[  FAILED  \] [0-9]+ test' "$work/tests-$shard.log" | tr '\n' ' ')"
        ((rc > worst)) && worst=$rc
    done
    for ((shard = 0; shard < shards; ++shard)); do
        echo "#### shard $shard"
        cat "$work/tests-$shard.log"
    done > "$OUT/tests.log"
    # Each test by name, once: a shard prints a failure twice (where it happened, in its summary).
    cat "$work"/tests-*.log > "$work/all-tests.txt"
    names() { grep -E "^\[ +$1 +\] [^ ]" "$work/all-tests.txt" | sed -E 's/^\[[^]]*\] ([^ ,]+).*/\1/' |
        grep -v '^[0-9]' | sort -u; }
    names OK > "$work/ok"
    names FAILED > "$work/failed"
    names SKIPPED > "$work/skipped"
    names RUN > "$work/ran"
    passed=$(grep -c . "$work/ok")
    failed=$(grep -c . "$work/failed")
    echo "tests: $passed passed, $failed failed, $(grep -c . "$work/skipped") skipped"
    sed 's/^/failed: /' "$work/failed"
    # Started and never finished: the shard's limit stopped it there.
    sort -u "$work/ok" "$work/failed" "$work/skipped" | comm -23 "$work/ran" - | sed 's/^/cut short: /'
    note "lane safety, width 1 ($shards shards)" "exit $worst, $((SECONDS - t0)) s, $passed passed, $failed failed"
fi

# The stability suite (`fgr check`) on every plugin scene at packet width 1 (a GPU's layout), as
# many at once as the test shards, all within one limit.
echo
echo "== fgr check: the numerical stability suite at packet width 1"
checks=()  # scene files (a scene id in the quick trial)
if [[ $quick == 1 ]]; then
    checks=(mandelbulb)
else
    checks=("$kit"/lib/fgr/plugins/*.so)
fi
remaining=$(left)
check_limit=120
((check_limit > remaining - 5)) && check_limit=$((remaining - 5))
if ((check_limit < 15)); then
    echo "== fgr check: skipped, the budget is spent"
    note "fgr check, width 1" "skipped (budget)"
else
    t0=$SECONDS
    deadline=$((SECONDS + check_limit))
    echo "${#checks[@]} scenes, $shards at once, limit $check_limit s"
    : > "$work/checks"
    declare -A live=()  # the checks still running, by process id
    for scene in "${checks[@]}"; do
        name=$(basename "$scene" .so)
        limit=$((deadline - SECONDS))
        if ((limit < 5)); then
            echo "$name skipped" >> "$work/checks"
            continue
        fi
        (
            timeout -k 5 "$limit" "${fgr[@]}" check "$scene" --packet-width 1 "${dev[@]}" \
                > "$work/check-$name.log" 2>&1
            echo "$name $?" >> "$work/checks"
        ) &
        live[$!]=1
        if ((${#live[@]} >= shards)); then
            # -p names the one that ended, so it is not waited for again (bash: "no such job").
            wait -n -p ended "${!live[@]}"
            unset "live[$ended]"
        fi
    done
    # By id: a bare `wait` would wait for the tee of this script's output too, which never ends.
    ((${#live[@]} > 0)) && wait "${!live[@]}"
    for scene in "${checks[@]}"; do
        name=$(basename "$scene" .so)
        echo "#### $name"
        cat "$work/check-$name.log" 2> /dev/null
    done > "$OUT/checks.log"
    checked=$(grep -c ' 0$' "$work/checks")
    echo "checks: $checked of ${#checks[@]} passed"
    awk '$2 != 0 { print "check not passed: " $1 " (" ($2 == "skipped" ? "skipped" : "exit " $2) ")" }' \
        "$work/checks"
    note "fgr check, width 1 (${#checks[@]} scenes)" "$checked passed, $((SECONDS - t0)) s"
fi

# The benches: both scenes at the full resolution in every mode they have.
failed=()  # SCENE/MODE of each bench that failed
for scene in mandelbulb benchmark; do
    for mode in shaded path brute; do
        step_rc=0
        step "bench $scene $mode ${width}x$height" 60 "${fgr[@]}" bench "$scene" --mode "$mode" \
            "${size[@]}" --duration "$duration" "${dev[@]}" -o "$work/bench-$scene-$mode"
        ((step_rc == 0)) || failed+=("$scene/$mode")
    done
done

# A failed bench narrowed down: the same scene and mode rendered small at each packet width (a
# fault at some widths only is the layout's, at every width the scene's), and the path mode also
# without regrouping (its batch of lanes changes with the width). Each render is short; a timeout
# reads as a hang.
for pair in "${failed[@]}" ${FGR_KIT_NARROW:-}; do
    scene=${pair%/*} mode=${pair#*/}
    variants=("1" "4" "8")  # rays per work-item, then flags
    samples=()
    if [[ $mode == path ]]; then
        variants+=("1 --no-regroup" "4 --no-regroup")
        samples=(--spp 4)
    fi
    for variant in "${variants[@]}"; do
        read -r packet_width flags <<< "$variant"
        # shellcheck disable=SC2086  # the flags are words
        step "narrow $scene $mode w$packet_width ${flags#--}" 30 "${fgr[@]}" render "$scene" \
            --mode "$mode" --width 320 --height 180 "${samples[@]}" --packet-width "$packet_width" \
            $flags "${dev[@]}" -o "$work/narrow.png"
    done
done
step "render mandelbulb shaded ${width}x$height" 40 "${fgr[@]}" render mandelbulb "${size[@]}" \
    --stats "${dev[@]}" -o "$OUT/mandelbulb-shaded-${width}x$height.png"
step "render mandelbulb path ${width}x$height" 40 "${fgr[@]}" render mandelbulb --mode path \
    --spp "$spp" --time-limit 20 "${size[@]}" "${dev[@]}" -o "$OUT/mandelbulb-path-${width}x$height.png"

echo
echo "== the benches (mean fps)"
for csv in "$work"/bench-*.csv; do
    [[ -e $csv ]] || continue
    echo "-- $(basename "$csv" .csv)"
    cat "$csv"
done
extras=$(cd "$work" && ls bench-* 2>/dev/null)
[[ -n $extras ]] && tar -czf "$OUT/bench.tar.gz" -C "$work" $extras
echo
echo "== summary (device $device, $((SECONDS - start)) s)"
printf '%s\n' "${summary[@]}"
rm -rf "$work"
exec >&- 2>&-
wait "$tee_pid"
exit 0
