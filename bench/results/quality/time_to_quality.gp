# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
16.2,0.679434,1
29.7,0.492112,2
31.4,0.277622,4
59.2,0.182084,8
139.2,0.125583,16
259.2,0.0930606,32
528.4,0.0726488,64
902.3,0.0554946,128
1911.7,0.0397952,256
3696.5,0.0254598,512
7578.7,0.015198,1024
14501.6,0.00841318,2048
29233.7,0.00443635,4096
EOD
$ladder1 << EOD
14.9,0.679434,1
27.2,0.492112,2
30.8,0.277622,4
60.4,0.182084,8
117.7,0.125583,16
214.8,0.0930606,32
640.5,0.0726488,64
902.6,0.0554946,128
1734.2,0.0397952,256
3258.6,0.0254598,512
7008.5,0.015198,1024
12688.9,0.00841319,2048
25686,0.00443634,4096
EOD
$ladder2 << EOD
2680.9,0.226553,0.3
4668.5,0.170651,0.2
7114.6,0.0875324,0.1
9643.7,0.0402792,0.05
12640.9,0.0166099,0.03
16131.4,0.00809123,0.02
22904.5,0.00460345,0.01
EOD
$ladder3 << EOD
2750.3,0.0764691,0.3
4592.9,0.0568772,0.2
7266.8,0.029751,0.1
9545.4,0.0143538,0.05
12704.7,0.00705181,0.03
15967,0.00436068,0.02
EOD
$ladder4 << EOD
56.4,0.162343,2
65.4,0.0982178,4
85.9,0.0651233,8
149,0.0487644,16
247.2,0.0372823,32
517.5,0.0286053,64
920.3,0.0207968,128
1811.2,0.014362,256
3216.2,0.00989205,512
6647.8,0.00656614,1024
12674.6,0.00430516,2048
EOD
$ladder5 << EOD
9.3,0.527655,1
16.4,0.417908,2
29.2,0.287906,4
56.4,0.166686,8
96.6,0.0935784,16
181,0.0484547,32
360.5,0.0243385,64
718.6,0.0119929,128
1424.8,0.00643184,256
2833.1,0.00334591,512
EOD
$ladder6 << EOD
7.5,0.527655,1
19.6,0.417908,2
19.5,0.287906,4
35.1,0.166686,8
69.2,0.0935784,16
199.8,0.0484547,32
301.2,0.0243385,64
663.8,0.0119929,128
1162.3,0.00643184,256
2295,0.00334591,512
EOD
$ladder7 << EOD
1723.3,0.13141,0.3
1849.6,0.0686563,0.2
2049.7,0.0173372,0.1
3659.7,0.00421046,0.05
EOD
$ladder8 << EOD
1705.1,0.0634635,0.3
1935.4,0.0314958,0.2
2108,0.00951191,0.1
3828.4,0.00333555,0.05
EOD
$ladder9 << EOD
44.6,0.279108,2
51.3,0.170514,4
72.6,0.0896362,8
113.2,0.049081,16
228.3,0.0255653,32
431.6,0.0141873,64
726.9,0.0081087,128
1181.6,0.00519872,256
2322,0.00306702,512
EOD
$ladder10 << EOD
11.6,0.878057,1
28.6,0.824522,2
64.7,0.766667,4
98.3,0.685283,8
228.2,0.578575,16
369.1,0.448926,32
807.7,0.312494,64
1465.4,0.196795,128
2905.4,0.112961,256
5879.5,0.060354,512
11798.7,0.0323506,1024
23865.6,0.0171026,2048
47590.7,0.00936179,4096
EOD
$ladder11 << EOD
19.2,0.878057,1
34.1,0.824522,2
52.2,0.766667,4
86.9,0.685283,8
171.4,0.578575,16
342.3,0.448926,32
706.6,0.312494,64
1447.9,0.196795,128
2759,0.112961,256
5459.7,0.0603539,512
10866.2,0.0323506,1024
21972.3,0.0171026,2048
45165.2,0.00936178,4096
EOD
$ladder12 << EOD
15037.5,0.573624,0.3
14295.3,0.392683,0.2
8966.4,0.138688,0.1
13672.7,0.0377979,0.05
29863,0.0147088,0.03
40455.2,0.00992075,0.02
43657.6,0.00944024,0.01
44795.5,0.00943577,0.005
43381.9,0.00943578,0.003
43530.7,0.00943578,0.002
EOD
$ladder13 << EOD
15426.7,0.0525285,0.3
14206.9,0.0292362,0.2
8975.5,0.012631,0.1
14089.4,0.00581356,0.05
29634.5,0.00372145,0.03
EOD
$ladder14 << EOD
58,0.256775,2
88.6,0.149252,4
137.8,0.0951069,8
208.1,0.0592005,16
382.4,0.038491,32
726.1,0.0262853,64
1499.8,0.0183865,128
2767.5,0.0121649,256
5543.4,0.00782253,512
10746.4,0.00553683,1024
21609.5,0.00415896,2048
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
     $ladder0 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle, \
     $ladder1 using 1:2 with linespoints lw 2 pt 2 lc 2 title '+ regrouping' noenhanced, \
     $ladder1 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 2 notitle, \
     $ladder2 using 1:2 with linespoints lw 2 pt 3 lc 3 title '+ adaptive' noenhanced, \
     $ladder2 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 3 notitle, \
     $ladder3 using 1:2 with linespoints lw 2 pt 4 lc 4 title '+ denoiser' noenhanced, \
     $ladder3 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 4 notitle, \
     $ladder4 using 1:2 with linespoints lw 2 pt 5 lc 5 title 'regrouping + denoiser' noenhanced, \
     $ladder4 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 5 notitle
set title 'mandelbulb-studio' noenhanced
plot 0.005 with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = 0.005', \
     $ladder5 using 1:2 with linespoints lw 2 pt 1 lc 1 title 'path tracer' noenhanced, \
     $ladder5 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle, \
     $ladder6 using 1:2 with linespoints lw 2 pt 2 lc 2 title '+ regrouping' noenhanced, \
     $ladder6 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 2 notitle, \
     $ladder7 using 1:2 with linespoints lw 2 pt 3 lc 3 title '+ adaptive' noenhanced, \
     $ladder7 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 3 notitle, \
     $ladder8 using 1:2 with linespoints lw 2 pt 4 lc 4 title '+ denoiser' noenhanced, \
     $ladder8 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 4 notitle, \
     $ladder9 using 1:2 with linespoints lw 2 pt 5 lc 5 title 'regrouping + denoiser' noenhanced, \
     $ladder9 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 5 notitle
set title 'menger-room' noenhanced
plot 0.005 with lines lw 2 dt 2 lc rgb '#666666' title '1 - SSIM = 0.005', \
     $ladder10 using 1:2 with linespoints lw 2 pt 1 lc 1 title 'path tracer' noenhanced, \
     $ladder10 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 1 notitle, \
     $ladder11 using 1:2 with linespoints lw 2 pt 2 lc 2 title '+ regrouping' noenhanced, \
     $ladder11 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 2 notitle, \
     $ladder12 using 1:2 with linespoints lw 2 pt 3 lc 3 title '+ adaptive' noenhanced, \
     $ladder12 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 3 notitle, \
     $ladder13 using 1:2 with linespoints lw 2 pt 4 lc 4 title '+ denoiser' noenhanced, \
     $ladder13 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 4 notitle, \
     $ladder14 using 1:2 with linespoints lw 2 pt 5 lc 5 title 'regrouping + denoiser' noenhanced, \
     $ladder14 using 1:2:3 with labels offset 0.6,0.6 font 'sans,7' tc lt 5 notitle
unset multiplot
