#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# fgr's GPU checks, run from a kit that bench/gpu/pack.sh made (pack.sh copies this script into
# it): finds the NVIDIA OpenCL driver and points the kit's ICD loader at it (else OpenCL's own
# vendors, e.g. PoCL, are used), then runs, each step under a time limit and whatever the last one
# did:
#   fgr info and fgr info --math-check          the devices and the math self-test's verdicts
#   fgr render (shaded), 1920x1080, --stats     PNG to OUT, twice (cold and with the kernel cached)
#   fgr bench benchmark, fgr bench mandelbulb   the README's frame-rate protocol, 1280x720, 10 s;
#                                               the Mandelbulb in float and in double
#   fgr render --mode path, 1920x1080, --stats  PNG to OUT, 256 samples per pixel or 30 s
#   the deep zoom (bench/deep_zoom.json)        float and double, 1920x1080
#   fgr_tests: lane safety (float; the          sharded over the machine's cores; the tests open
#   Mandelbulb in double), packet widths        the first GPU (else the first device) themselves
#
#   bash .gpu-kit/run.sh
#
# Environment: OUT (results; default ./gpu-kit-out), FGR_KIT_BUDGET (seconds for all the steps,
# default 400: a step gets at most what is left), FGR_KIT_TESTS (the tests' gtest filter),
# FGR_KIT_SHARDS (test processes at once; default half the cores, at most 8), FGR_KIT_QUICK=1
# (small images, short benches, few tests: to try the kit on a CPU).
#
# OUT receives run.log (everything), tests.log, the two 1920x1080 PNGs and extras.tar.gz (the
# benches' JSON and CSV, the deep-zoom PNGs). Exit status 0 once all steps have run; each step's
# own is in the summary at the end.
set -uo pipefail
export LC_ALL=C

kit=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
OUT=${OUT:-$PWD/gpu-kit-out}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
work=$(mktemp -d /tmp/fgr-kit.XXXXXX)
budget=${FGR_KIT_BUDGET:-400}
quick=${FGR_KIT_QUICK:-0}
exec > >(tee -a "$OUT/run.log") 2>&1
tee_pid=$!

if [[ $quick == 1 ]]; then
    width=320 height=180 bench_args=(--duration 2) spp=4 path_limit=10
    default_tests='MathCheckTest.ScalarAndFloatBuiltinsPass:RenderTest.EveryPacketWidthRendersTheSameImage:Scenes/LaneSafety.*/mandelbulb_float'
else
    width=1920 height=1080 bench_args=() spp=256 path_limit=30
    # Every scene's float lane-safety case and the Mandelbulb's double one: NVIDIA's compiler took
    # about 40 s per double program on an H200, so all 18 double cases (3 programs each) and the
    # FloatAndDouble suite do not fit one run (FGR_KIT_TESTS names them).
    default_tests='Scenes/LaneSafety.*_float:Scenes/LaneSafety.*/mandelbulb_double'
    default_tests+=':MathCheckTest.*:RenderTest.*:*.EveryPacketWidth*:BruteModeTest.PacketWidthsAgreePerPixel'
    default_tests+=':SamplerTest.SameNumbersAtEveryWidthAndPrecision:BsdfTest.LanesDoNotAffectEachOther'
    default_tests+=':SdfRobustness.*'
fi
test_filter=${FGR_KIT_TESTS:-$default_tests}

start=$SECONDS
summary=()
left() { echo $((budget - (SECONDS - start))); }
note() { summary+=("$(printf '%-34s %s' "$1" "$2")"); }

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
    return 0
}

kv() { sed -n "s/^$1=//p" "$kit/kit.env"; }

echo "== fgr GPU kit, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
sed 's/^/kit: /' "$kit/kit.env"
echo "host: $(uname -srm), $(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME"), $(nproc) cores"
echo "system glibc: $(ldd --version 2>/dev/null | head -n 1 | awk '{ print $NF }')"
echo "OUT: $OUT"

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
    echo "no libnvidia-opencl.so.1: OpenCL's own vendors are used (PoCL where it is installed)"
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

step "info --math-check" 120 "${fgr[@]}" info --math-check
step "render shaded ${width}x$height" 90 "${fgr[@]}" render mandelbulb "${size[@]}" --stats "${dev[@]}" \
    -o "$OUT/mandelbulb-shaded-${width}x$height.png"
step "render shaded, kernel cached" 60 "${fgr[@]}" render mandelbulb "${size[@]}" --stats "${dev[@]}" \
    -o "$work/shaded-again.png"
step "bench benchmark 1280x720" 60 "${fgr[@]}" bench benchmark "${bench_args[@]}" "${dev[@]}" \
    -o "$work/bench-benchmark"
step "bench mandelbulb float" 60 "${fgr[@]}" bench mandelbulb --precision float "${bench_args[@]}" \
    "${dev[@]}" -o "$work/bench-mandelbulb-float"
step "bench mandelbulb double" 60 "${fgr[@]}" bench mandelbulb --precision double "${bench_args[@]}" \
    "${dev[@]}" -o "$work/bench-mandelbulb-double"
step "bench benchmark ${width}x$height" 45 "${fgr[@]}" bench benchmark "${size[@]}" --duration 5 \
    "${dev[@]}" -o "$work/bench-benchmark-${width}x$height"
step "render path ${width}x$height" 90 "${fgr[@]}" render mandelbulb --mode path --spp "$spp" \
    --time-limit "$path_limit" "${size[@]}" --stats "${dev[@]}" -o "$OUT/mandelbulb-path-${width}x$height.png"
for precision in float double; do
    step "deep zoom $precision" 45 "${fgr[@]}" render mandelbulb --camera-path "$kit/deep_zoom.json" \
        --time 0 --precision "$precision" "${size[@]}" --stats "${dev[@]}" \
        -o "$work/deep-zoom-$precision.png"
done

# The tests: paths compiled into fgr_tests (the build's plugin folder, the drivers' cache) are
# linked to the kit where they do not exist.
echo
echo "== fgr_tests"
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
# Tests that run fgr itself start the path compiled in: a script there starts the kit's fgr.
fgr_exe=$(kv test_fgr_exe)
if [[ -n $fgr_exe && ! -e $fgr_exe ]]; then
    if mkdir -p "$(dirname "$fgr_exe")" &&
        printf '#!/bin/sh\nexec %s "$@"\n' "$(printf '%q ' "${fgr[@]}")" > "$fgr_exe" &&
        chmod +x "$fgr_exe"; then
        echo "wrote $fgr_exe: starts the kit's fgr"
    else
        echo "cannot write $fgr_exe: the tests that run fgr will fail"
    fi
fi
cores=$(nproc)
shards=${FGR_KIT_SHARDS:-$((cores / 2 > 8 ? 8 : (cores / 2 < 1 ? 1 : cores / 2)))}
echo "filter: $test_filter"
echo "$shards shards at once; the tests open the first GPU, else the first device (open_device(-1))"
tests=("${launch[@]}" "$kit/bin/fgr_tests")
remaining=$(left)
if ((remaining < 20)); then
    echo "== fgr_tests: skipped, the budget is spent"
    note "fgr_tests" "skipped (budget)"
else
    t0=$SECONDS
    limit=$((remaining - 5))
    echo "== fgr_tests (limit $limit s)"
    pids=()
    for ((shard = 0; shard < shards; ++shard)); do
        GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard timeout -k 5 "$limit" "${tests[@]}" \
            --gtest_filter="$test_filter" > "$work/tests-$shard.log" 2>&1 &
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
    note "fgr_tests ($shards shards)" "exit $worst, $((SECONDS - t0)) s, $passed passed, $failed failed"
fi

echo
echo "== the benches"
for csv in "$work"/bench-*.csv; do
    [[ -e $csv ]] || continue
    echo "-- $(basename "$csv")"
    cat "$csv"
done
extras=$(cd "$work" && ls bench-* deep-zoom-*.png 2>/dev/null)
[[ -n $extras ]] && tar -czf "$OUT/extras.tar.gz" -C "$work" $extras
echo
echo "== summary (device $device, $((SECONDS - start)) s)"
printf '%s\n' "${summary[@]}"
rm -rf "$work"
exec >&- 2>&-
wait "$tee_pid"
exit 0
