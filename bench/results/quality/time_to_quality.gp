# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
35.7,0.679807,1
98.6,0.490754,2
196,0.2792,4
335,0.1846,8
761.7,0.127645,16
1483.7,0.095686,32
3116.8,0.075418,64
6282.5,0.0579959,128
12674.2,0.0424294,256
23500.4,0.0283183,512
41473.4,0.0181525,1024
EOD
$ladder1 << EOD
17.2,0.526665,1
28.2,0.41816,2
39.7,0.288541,4
88.8,0.165654,8
109.2,0.0932936,16
365.4,0.0470608,32
799.2,0.0243541,64
2690.5,0.0122443,128
5188.7,0.00641035,256
9435.9,0.00330911,512
20967.1,0.00184473,1024
EOD
$ladder2 << EOD
36.7,0.87766,1
67.8,0.824147,2
169.5,0.766849,4
323.3,0.68529,8
617.1,0.5786,16
1198.7,0.449303,32
2163.2,0.314112,64
3360.1,0.20025,128
6864,0.118075,256
13856.4,0.0666225,512
28289,0.0387367,1024
EOD
set multiplot layout 1,3
set logscale xy
set grid
set key top right font 'sans,9'
set xlabel 'render time (ms)'
set ylabel '1 - SSIM against the reference'
set title 'bulb-stage-sky' noenhanced
plot 0.005 with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = 0.005', \
     $ladder0 using 1:2 with linespoints lw 2 pt 1 lc 1 title 'path tracer' noenhanced, \
     $ladder0 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle
set title 'mandelbulb-studio' noenhanced
plot 0.005 with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = 0.005', \
     $ladder1 using 1:2 with linespoints lw 2 pt 1 lc 1 title 'path tracer' noenhanced, \
     $ladder1 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle
set title 'menger-room' noenhanced
plot 0.005 with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = 0.005', \
     $ladder2 using 1:2 with linespoints lw 2 pt 1 lc 1 title 'path tracer' noenhanced, \
     $ladder2 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle
unset multiplot
