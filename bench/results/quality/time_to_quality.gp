# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
27.1,0.679437,1
41.4,0.490433,2
87.9,0.278004,4
171,0.182895,8
254.7,0.12552,16
449.8,0.093132,32
914.8,0.0726086,64
1980.2,0.0554774,128
3796,0.0397298,256
7233.3,0.0254136,512
15406.1,0.0152031,1024
31982.4,0.00838516,2048
62611.5,0.00442167,4096
EOD
$ladder1 << EOD
26.4,0.679434,1
44.1,0.492112,2
64.4,0.277622,4
109.4,0.182084,8
225,0.125583,16
375.7,0.0930606,32
673.3,0.0726488,64
1406.5,0.0554946,128
2572.5,0.0397952,256
5051.4,0.0254598,512
10376.2,0.015198,1024
20388.9,0.00841318,2048
44186.7,0.00443635,4096
EOD
$ladder2 << EOD
26.5,0.679434,1
35.3,0.492112,2
53.3,0.277622,4
84,0.182084,8
165.1,0.125583,16
281.8,0.0930606,32
566.3,0.0726488,64
1177.4,0.0554946,128
2253.2,0.0397952,256
4383.7,0.0254598,512
9435.3,0.015198,1024
19219.4,0.00841319,2048
36887.3,0.00443634,4096
EOD
$ladder3 << EOD
3010.8,0.226553,0.3
5702.5,0.170651,0.2
8907.2,0.0875324,0.1
12565.8,0.0402792,0.05
16303.4,0.0166098,0.03
20138.9,0.00809125,0.02
30751.6,0.00460345,0.01
EOD
$ladder4 << EOD
3215.2,0.09068,0.3
5917.8,0.0687036,0.2
9225.6,0.0311906,0.1
12748.3,0.0120992,0.05
16821,0.00560858,0.03
20446.9,0.00325735,0.02
EOD
$ladder5 << EOD
153.2,0.164791,2
173.8,0.110123,4
211.7,0.0823699,8
259.2,0.060038,16
374.6,0.0422856,32
705.1,0.0307448,64
1229.3,0.0190176,128
2223.3,0.0117806,256
4634.3,0.00765495,512
9570.1,0.00494589,1024
EOD
$ladder6 << EOD
23.5,0.526665,1
29.5,0.41816,2
44.2,0.288541,4
85.5,0.165654,8
151.3,0.0932936,16
2040,0.0470608,32
690.8,0.0243541,64
1195,0.0122443,128
2344.1,0.00641035,256
4769.2,0.00330911,512
EOD
$ladder7 << EOD
24.3,0.527655,1
26.2,0.417908,2
53.9,0.287906,4
77.4,0.166686,8
137.8,0.0935784,16
215.3,0.0484547,32
426.9,0.0243385,64
858.1,0.0119929,128
1546.7,0.00643184,256
3089.9,0.00334591,512
EOD
$ladder8 << EOD
21.4,0.527655,1
29.6,0.417908,2
45.1,0.287906,4
67,0.166686,8
116,0.0935784,16
210.1,0.0484547,32
433.7,0.0243385,64
869.7,0.0119929,128
1625.7,0.00643184,256
3150.3,0.00334591,512
EOD
$ladder9 << EOD
2114.2,0.13141,0.3
2512.4,0.0686563,0.2
2789.9,0.0173372,0.1
5339.5,0.00421046,0.05
EOD
$ladder10 << EOD
2271.5,0.026807,0.3
2744.4,0.0140166,0.2
2948.7,0.00525842,0.1
5407.1,0.00242811,0.05
EOD
$ladder11 << EOD
144,0.14722,2
161.1,0.0772026,4
186.2,0.039225,8
240.1,0.0218311,16
329.4,0.0124875,32
563.4,0.00781045,64
985.3,0.00494012,128
EOD
$ladder12 << EOD
22.9,0.878057,1
49.8,0.824522,2
82.2,0.766667,4
157.6,0.685283,8
301,0.578575,16
522.8,0.448926,32
1124.8,0.312494,64
2145.5,0.196795,128
4263.8,0.112961,256
8567.4,0.060354,512
16876.3,0.0323506,1024
34132,0.0171026,2048
68449.8,0.00936179,4096
EOD
$ladder13 << EOD
22.4,0.878057,1
51.8,0.824522,2
71.2,0.766667,4
135.1,0.685283,8
258.4,0.578575,16
455.7,0.448926,32
906.6,0.312494,64
1775.3,0.196795,128
3519.7,0.112961,256
7070.1,0.060354,512
14211,0.0323506,1024
28913.5,0.0171026,2048
56599.9,0.00936179,4096
EOD
$ladder14 << EOD
34.7,0.878057,1
50.2,0.824522,2
80.7,0.766667,4
130.6,0.685283,8
231.8,0.578575,16
437.4,0.448926,32
901.5,0.312494,64
1666.9,0.196795,128
3319.4,0.112961,256
6711.7,0.0603539,512
13662.7,0.0323506,1024
26939,0.0171026,2048
56231.1,0.00936178,4096
EOD
$ladder15 << EOD
19019.9,0.573624,0.3
17708.5,0.392683,0.2
12023.9,0.138688,0.1
18051.4,0.037798,0.05
35627.3,0.0147089,0.03
47676.6,0.00992075,0.02
51500.9,0.00944025,0.01
51632.9,0.00943577,0.005
51344.4,0.00943578,0.003
52444.3,0.00943578,0.002
EOD
$ladder16 << EOD
20008.9,0.0489253,0.3
17591.2,0.0264235,0.2
11813.8,0.0111529,0.1
18113.9,0.00480722,0.05
EOD
$ladder17 << EOD
186.9,0.255981,2
214.3,0.143831,4
289.9,0.0854208,8
320.1,0.0507788,16
528.1,0.0323639,32
931.5,0.0222647,64
1776.8,0.01589,128
3409.5,0.0109536,256
6730.2,0.00704428,512
13965.8,0.00457732,1024
EOD
set multiplot layout 1,3
set logscale xy
set grid
set key top right font 'sans,9'
set xlabel 'render time (ms)'
set ylabel '1 - SSIM against the reference'
set title 'bulb-stage-sky' noenhanced
plot 0.005 with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = 0.005', \
     $ladder0 using 1:2 with linespoints lw 2 pt 1 lc 1 title 'previous release' noenhanced, \
     $ladder0 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle, \
     $ladder1 using 1:2 with linespoints lw 2 pt 2 lc 2 title 'path tracer' noenhanced, \
     $ladder1 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 2 notitle, \
     $ladder2 using 1:2 with linespoints lw 2 pt 3 lc 3 title '+ regrouping' noenhanced, \
     $ladder2 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 3 notitle, \
     $ladder3 using 1:2 with linespoints lw 2 pt 4 lc 4 title '+ adaptive' noenhanced, \
     $ladder3 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 4 notitle, \
     $ladder4 using 1:2 with linespoints lw 2 pt 5 lc 5 title '+ denoiser' noenhanced, \
     $ladder4 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 5 notitle, \
     $ladder5 using 1:2 with linespoints lw 2 pt 6 lc 6 title 'regrouping + denoiser' noenhanced, \
     $ladder5 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 6 notitle
set title 'mandelbulb-studio' noenhanced
plot 0.005 with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = 0.005', \
     $ladder6 using 1:2 with linespoints lw 2 pt 1 lc 1 title 'previous release' noenhanced, \
     $ladder6 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle, \
     $ladder7 using 1:2 with linespoints lw 2 pt 2 lc 2 title 'path tracer' noenhanced, \
     $ladder7 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 2 notitle, \
     $ladder8 using 1:2 with linespoints lw 2 pt 3 lc 3 title '+ regrouping' noenhanced, \
     $ladder8 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 3 notitle, \
     $ladder9 using 1:2 with linespoints lw 2 pt 4 lc 4 title '+ adaptive' noenhanced, \
     $ladder9 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 4 notitle, \
     $ladder10 using 1:2 with linespoints lw 2 pt 5 lc 5 title '+ denoiser' noenhanced, \
     $ladder10 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 5 notitle, \
     $ladder11 using 1:2 with linespoints lw 2 pt 6 lc 6 title 'regrouping + denoiser' noenhanced, \
     $ladder11 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 6 notitle
set title 'menger-room' noenhanced
plot 0.005 with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = 0.005', \
     $ladder12 using 1:2 with linespoints lw 2 pt 1 lc 1 title 'previous release' noenhanced, \
     $ladder12 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle, \
     $ladder13 using 1:2 with linespoints lw 2 pt 2 lc 2 title 'path tracer' noenhanced, \
     $ladder13 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 2 notitle, \
     $ladder14 using 1:2 with linespoints lw 2 pt 3 lc 3 title '+ regrouping' noenhanced, \
     $ladder14 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 3 notitle, \
     $ladder15 using 1:2 with linespoints lw 2 pt 4 lc 4 title '+ adaptive' noenhanced, \
     $ladder15 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 4 notitle, \
     $ladder16 using 1:2 with linespoints lw 2 pt 5 lc 5 title '+ denoiser' noenhanced, \
     $ladder16 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 5 notitle, \
     $ladder17 using 1:2 with linespoints lw 2 pt 6 lc 6 title 'regrouping + denoiser' noenhanced, \
     $ladder17 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 6 notitle
unset multiplot
