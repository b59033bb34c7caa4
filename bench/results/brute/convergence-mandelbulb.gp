# SPDX-License-Identifier: Apache-2.0
set terminal pngcairo size 960,400 font ',10'
set output 'convergence-mandelbulb.png'
set datafile separator ','
set multiplot layout 1,2 title 'Brute force on mandelbulb: depth against the sphere-traced depth (shaded mode)'
set grid
set logscale xy
set xlabel 'render time (ms)'
set ylabel 'disagreeing pixels (%): > 4 footprints, or hit in one only'
set arrow 1 from 30.4947, graph 0 to 30.4947, graph 1 nohead dashtype 2 lc rgb '#888888'
set label 1 'reference: 30 ms' at 30.4947, graph 0.95 offset 0.5,0 textcolor rgb '#666666'
plot 'convergence-mandelbulb.csv' skip 1 using 2:4:1 with linespoints pt 7 title 'passes (labelled)', \
     'convergence-mandelbulb.csv' skip 1 using 2:4:(sprintf('%d', $1)) with labels offset 0,1 notitle
unset arrow 1
unset label 1
set logscale x 2
set xlabel 'passes'
set ylabel 'mean depth error where both hit (footprints)'
plot 'convergence-mandelbulb.csv' skip 1 using 1:7 with linespoints pt 7 title 'mean |t - t_{ref}|'
unset multiplot
