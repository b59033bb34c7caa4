#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The path tracer's convergence plot (docs/user-guide/render-modes.md): RMS error against a 4096-spp render of the
# Mandelbulb in the studio (16x16, four bounces) at 4 to 256 samples per pixel, with independent
# and with stratified samples, as tests/render/test_path_tracer.cpp's ErrorFallsAsOneOverRootSamples
# measures it (the test prints the figures; this plots them with gnuplot). Run from the
# repository root after ./build.sh test has built the tests.
set -euo pipefail
tests=${FGR_TESTS:-build/bin/fgr_tests}
out=bench/results/path
mkdir -p "$out"
"$tests" --gtest_filter=PathTracer.ErrorFallsAsOneOverRootSamples |
    sed -n 's/^\(independent\|stratified\), spp \([0-9]*\): RMSE \([0-9.]*\)$/\1 \2 \3/p' \
        > "$out/convergence.dat"
cat > "$out/convergence.gp" <<'GP'
set terminal pngcairo size 640,420 font ",10"
set output "bench/results/path/convergence.png"
set logscale xy
set xlabel "samples per pixel"
set ylabel "RMSE against 4096 spp"
set key top right
set grid
set title "Path tracer convergence (Mandelbulb, studio, 4 bounces)"
set fit quiet
set fit logfile "/dev/null"
f(x) = a * x**-0.5
a = 0.3
fit f(x) "< grep independent bench/results/path/convergence.dat" using 2:3 via a
plot "< grep independent bench/results/path/convergence.dat" using 2:3 with linespoints \
         title "independent samples", \
     "< grep stratified bench/results/path/convergence.dat" using 2:3 with linespoints \
         title "stratified (Owen-scrambled Sobol)", \
     f(x) with lines dashtype 2 title "spp^{-1/2}"
GP
gnuplot "$out/convergence.gp" 2>/dev/null
echo "wrote $out/convergence.png"
