# SPDX-License-Identifier: Apache-2.0
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
