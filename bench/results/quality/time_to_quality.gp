# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
19.9,0.679437,1
37.6,0.490433,2
71.2,0.278004,4
144.7,0.182895,8
254.9,0.12552,16
477.4,0.093132,32
955.2,0.0726086,64
1982.4,0.0554774,128
3906,0.0397298,256
8057.4,0.0254136,512
15860,0.0152031,1024
31068.8,0.00838516,2048
63507.7,0.00442167,4096
EOD
$ladder1 << EOD
16.8,0.733838,1
28.3,0.507393,2
65.6,0.365135,4
103.4,0.229268,8
188.3,0.147467,16
368.2,0.104,32
737.9,0.0780414,64
1461.3,0.0572984,128
2945,0.038753,256
5796.7,0.0230191,512
11671.6,0.0124955,1024
23429.1,0.00659621,2048
48376.6,0.00358191,4096
EOD
$ladder2 << EOD
15.4,0.733838,1
26.4,0.507393,2
47.2,0.365135,4
80,0.229268,8
142.2,0.147467,16
276.7,0.104,32
568.7,0.0780414,64
1117.2,0.0572984,128
2277.7,0.038753,256
4421.9,0.0230191,512
9073.9,0.0124955,1024
17953.3,0.00659621,2048
36693,0.00358191,4096
EOD
$ladder3 << EOD
262.6,0.251605,0.3
484.5,0.179233,0.2
1966.2,0.0812154,0.1
6543.1,0.0304479,0.05
13386.6,0.0129051,0.03
20432.4,0.00672311,0.02
31211.9,0.00399227,0.01
EOD
$ladder4 << EOD
306.9,0.0863555,0.3
540.8,0.0644553,0.2
1991.8,0.0281829,0.1
6677.9,0.0091087,0.05
12967,0.00460315,0.03
EOD
$ladder5 << EOD
68.2,0.173559,2
87.5,0.125426,4
120.7,0.0879869,8
193.7,0.0622663,16
329.9,0.04403,32
588.2,0.0334358,64
1148,0.0191719,128
2346.1,0.0112355,256
4525.5,0.00742361,512
8936.2,0.00465007,1024
EOD
$ladder6 << EOD
13.3,0.526665,1
22.2,0.41816,2
41.9,0.288541,4
73.7,0.165654,8
191.8,0.0932936,16
368.4,0.0470608,32
602.5,0.0243541,64
1191.9,0.0122443,128
2233.6,0.00641035,256
4595.3,0.00330911,512
EOD
$ladder7 << EOD
10.7,0.489177,1
27.6,0.349337,2
43.9,0.225053,4
58.7,0.127477,8
107.3,0.0620285,16
258.2,0.0307346,32
406.6,0.0153421,64
784.7,0.0073931,128
1575.7,0.00367078,256
EOD
$ladder8 << EOD
10.4,0.489177,1
20.2,0.349337,2
32.9,0.225053,4
58.3,0.127477,8
109.6,0.0620285,16
217.4,0.0307346,32
395.9,0.0153421,64
822.7,0.0073931,128
1620.1,0.00367078,256
EOD
$ladder9 << EOD
155.8,0.126376,0.3
293.4,0.0717751,0.2
875.9,0.0187019,0.1
3117.6,0.00415748,0.05
EOD
$ladder10 << EOD
186.7,0.0255399,0.3
331.9,0.0146342,0.2
911.7,0.00545444,0.1
3076.1,0.00233695,0.05
EOD
$ladder11 << EOD
59.7,0.113501,2
71.6,0.0562451,4
97.9,0.0292867,8
148.5,0.0166871,16
268.5,0.0101339,32
450.5,0.00599932,64
836.5,0.00380326,128
EOD
$ladder12 << EOD
19.1,0.878057,1
38,0.824522,2
81.7,0.766667,4
166.8,0.685283,8
300,0.578575,16
569.9,0.448926,32
1124.3,0.312494,64
2303,0.196795,128
4523.6,0.112961,256
8901.5,0.060354,512
17900.9,0.0323506,1024
35026.6,0.0171026,2048
68566.5,0.00936179,4096
EOD
$ladder13 << EOD
15.6,0.875514,1
32.6,0.823442,2
64.7,0.765984,4
131.2,0.685899,8
254.2,0.577039,16
489.4,0.447081,32
965.9,0.308244,64
1931.4,0.191887,128
3787.2,0.111844,256
7674.2,0.0609489,512
15497.8,0.0320629,1024
29468.5,0.0171414,2048
58867.5,0.00907779,4096
EOD
$ladder14 << EOD
21.9,0.875514,1
35.1,0.823442,2
63.2,0.765984,4
121.2,0.685899,8
233.3,0.577039,16
441.5,0.447081,32
860.9,0.308244,64
1773,0.191887,128
3538.6,0.111844,256
7069.7,0.0609489,512
14234.5,0.0320629,1024
26934.2,0.0171414,2048
53801.1,0.00907779,4096
EOD
$ladder15 << EOD
436.3,0.586675,0.3
1039.8,0.415451,0.2
4014.8,0.146554,0.1
14625.9,0.0394294,0.05
35787.1,0.0152732,0.03
48231.5,0.0100739,0.02
52278.4,0.00961895,0.01
53480.9,0.00961337,0.005
52802.7,0.00961337,0.003
52288.4,0.00961337,0.002
EOD
$ladder16 << EOD
492.4,0.0529127,0.3
1036.5,0.027369,0.2
3946,0.0116223,0.1
14573,0.00513603,0.05
35659.1,0.0027961,0.03
EOD
$ladder17 << EOD
78.2,0.254376,2
112.9,0.158032,4
164,0.0901042,8
270.1,0.0543485,16
477.9,0.0317768,32
936.3,0.0216334,64
1834.4,0.0146525,128
3443.7,0.0104453,256
6944.9,0.00706266,512
14022.5,0.00430111,1024
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
