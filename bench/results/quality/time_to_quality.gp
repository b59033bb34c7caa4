# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
31.4,0.679437,1
39.1,0.490433,2
73.9,0.278004,4
137.6,0.182895,8
229.6,0.12552,16
471.1,0.093132,32
952.2,0.0726086,64
1791.1,0.0554774,128
3509.6,0.0397298,256
7007.8,0.0254136,512
14355.8,0.0152031,1024
29010.7,0.00838516,2048
57175.4,0.00442167,4096
EOD
$ladder1 << EOD
25.2,0.679838,1
35.2,0.501202,2
56.6,0.289471,4
97.9,0.189879,8
169.6,0.125513,16
312.8,0.0950835,32
658.6,0.0758347,64
1331.9,0.0596405,128
2457.7,0.0407584,256
4756.7,0.0257141,512
9964.1,0.0149624,1024
20343.1,0.00824788,2048
40520.4,0.0045655,4096
EOD
$ladder2 << EOD
26.2,0.679838,1
35.3,0.501202,2
51.6,0.289471,4
84.4,0.189879,8
153,0.125513,16
284.4,0.0950835,32
548.5,0.0758347,64
1115.9,0.0596405,128
2119.1,0.0407584,256
4241.4,0.0257141,512
8818.7,0.0149624,1024
17274.4,0.00824788,2048
36681,0.0045655,4096
EOD
$ladder3 << EOD
242,0.230157,0.3
449.3,0.177048,0.2
1643.5,0.0926967,0.1
5370,0.0422431,0.05
11092.8,0.0183114,0.03
16461.6,0.00963259,0.02
26996.1,0.00520424,0.01
29741.7,0.00482858,0.005
EOD
$ladder4 << EOD
303.3,0.0898234,0.3
528.4,0.0735437,0.2
1707.6,0.0369741,0.1
5509.3,0.01334,0.05
11104.2,0.00720795,0.03
16515.4,0.00424607,0.02
EOD
$ladder5 << EOD
89.8,0.16637,2
96.7,0.117146,4
121.2,0.0838355,8
192.6,0.0581699,16
337.1,0.0425914,32
585.7,0.0324726,64
1086.8,0.0185147,128
2138.3,0.011689,256
4237.7,0.00758369,512
8584.8,0.00505021,1024
17313.9,0.00344084,2048
EOD
$ladder6 << EOD
22.7,0.526665,1
29.4,0.41816,2
46.4,0.288541,4
83.6,0.165654,8
198.7,0.0932936,16
315.6,0.0470608,32
579.1,0.0243541,64
1159.9,0.0122443,128
2176.2,0.00641035,256
4628.9,0.00330911,512
EOD
$ladder7 << EOD
22,0.544217,1
30.5,0.398533,2
39.2,0.260345,4
62.4,0.137098,8
150.7,0.0600957,16
284.3,0.0300451,32
390.7,0.0142564,64
798.3,0.00668704,128
1738,0.00326316,256
EOD
$ladder8 << EOD
19.3,0.544217,1
25.7,0.398533,2
42.3,0.260345,4
71.8,0.137098,8
112.8,0.0600957,16
203.4,0.0300451,32
403.9,0.0142564,64
789.6,0.00668704,128
1495.6,0.00326316,256
EOD
$ladder9 << EOD
189.2,0.113225,0.3
330.3,0.0595144,0.2
980,0.0133076,0.1
3540.1,0.00297387,0.05
EOD
$ladder10 << EOD
226.6,0.0235146,0.3
361.4,0.0129774,0.2
1111.1,0.00466969,0.1
EOD
$ladder11 << EOD
67.9,0.124714,2
105.6,0.0665138,4
121.5,0.0324589,8
162.2,0.0169375,16
258,0.0101258,32
480,0.00587016,64
842.9,0.00369862,128
EOD
$ladder12 << EOD
23.9,0.878057,1
46.3,0.824522,2
80.7,0.766667,4
145,0.685283,8
277.4,0.578575,16
542.3,0.448926,32
1118.8,0.312494,64
2194.8,0.196795,128
4199.3,0.112961,256
9161.4,0.060354,512
16901.2,0.0323506,1024
34927.2,0.0171026,2048
68785.9,0.00936179,4096
EOD
$ladder13 << EOD
16.8,0.875514,1
35.4,0.823442,2
79,0.765984,4
112.5,0.685899,8
236.6,0.577039,16
481.3,0.447081,32
947.9,0.308244,64
1920.4,0.191887,128
3464.9,0.111844,256
7312,0.0609489,512
13784.3,0.0320629,1024
28689,0.0171414,2048
55492.5,0.00907779,4096
EOD
$ladder14 << EOD
29.4,0.875514,1
34,0.823442,2
63.2,0.765984,4
109.7,0.685899,8
208.2,0.577039,16
428.3,0.447081,32
856.5,0.308244,64
1730.3,0.191887,128
3230.7,0.111844,256
6943.4,0.0609489,512
13058,0.0320629,1024
27252.4,0.0171414,2048
53399.7,0.00907779,4096
EOD
$ladder15 << EOD
459.5,0.586675,0.3
996.4,0.415451,0.2
3741.8,0.146554,0.1
13200.1,0.0394294,0.05
32446.8,0.0152732,0.03
46158.4,0.0100739,0.02
48985.8,0.00961895,0.01
50573.6,0.00961337,0.005
49206.7,0.00961337,0.003
50735.5,0.00961337,0.002
EOD
$ladder16 << EOD
517.7,0.0529127,0.3
980.2,0.027369,0.2
3952.2,0.0116223,0.1
13198.2,0.00513603,0.05
32853.7,0.0027961,0.03
EOD
$ladder17 << EOD
85.5,0.254376,2
107,0.158032,4
156.4,0.0901042,8
259.5,0.0543485,16
489.1,0.0317768,32
930.3,0.0216334,64
1722.5,0.0146525,128
3567.8,0.0104453,256
6499.1,0.00706266,512
13064.8,0.00430111,1024
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
