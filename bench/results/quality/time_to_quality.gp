# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
21.4,0.679437,1
48.6,0.490433,2
75.5,0.278004,4
133.7,0.182895,8
243.2,0.12552,16
454.4,0.093132,32
904.2,0.0726086,64
1755.4,0.0554774,128
3522.4,0.0397298,256
7045.4,0.0254136,512
14005.4,0.0152031,1024
28144.1,0.00838516,2048
59006.8,0.00442167,4096
EOD
$ladder1 << EOD
25.9,0.679434,1
35.6,0.492112,2
62.3,0.277622,4
125.8,0.182084,8
180.3,0.125583,16
311.4,0.0930606,32
758.8,0.0726488,64
1223.5,0.0554946,128
2394.1,0.0397952,256
4802.5,0.0254598,512
9651.5,0.015198,1024
20131.3,0.00841318,2048
39808.2,0.00443635,4096
EOD
$ladder2 << EOD
26.5,0.679434,1
34.7,0.492112,2
55.6,0.277622,4
82.9,0.182084,8
162.8,0.125583,16
276.2,0.0930606,32
542.1,0.0726488,64
1061.4,0.0554946,128
2138.7,0.0397952,256
4238.5,0.0254598,512
8375.7,0.015198,1024
17717.7,0.00841319,2048
34423.5,0.00443634,4096
EOD
$ladder3 << EOD
3336.4,0.226553,0.3
5372.4,0.170651,0.2
8552,0.0875324,0.1
12418.9,0.0402792,0.05
16303.4,0.0166098,0.03
19552.7,0.00809125,0.02
28371,0.00460345,0.01
EOD
$ladder4 << EOD
3127.5,0.09068,0.3
5456.7,0.0687036,0.2
8808.6,0.0311906,0.1
12430.6,0.0120992,0.05
15553.7,0.00560858,0.03
19377.3,0.00325735,0.02
EOD
$ladder5 << EOD
92.9,0.164791,2
95.4,0.110123,4
132.7,0.0823699,8
188.3,0.060038,16
331.7,0.0422856,32
582.2,0.0307448,64
1113.3,0.0190176,128
2174.5,0.0117806,256
4302.8,0.00765495,512
8350.8,0.00494589,1024
EOD
$ladder6 << EOD
16.1,0.526665,1
28.5,0.41816,2
45.2,0.288541,4
110.4,0.165654,8
127.7,0.0932936,16
382,0.0470608,32
524.4,0.0243541,64
963.8,0.0122443,128
1930.5,0.00641035,256
3962.4,0.00330911,512
EOD
$ladder7 << EOD
17,0.527655,1
27.5,0.417908,2
39.4,0.287906,4
54.7,0.166686,8
127.7,0.0935784,16
251.2,0.0484547,32
355.5,0.0243385,64
670.6,0.0119929,128
1257.1,0.00643184,256
2492.3,0.00334591,512
EOD
$ladder8 << EOD
23.5,0.527655,1
30.5,0.417908,2
42.2,0.287906,4
60.7,0.166686,8
102.4,0.0935784,16
186.3,0.0484547,32
351.3,0.0243385,64
700.3,0.0119929,128
1390.7,0.00643184,256
2742.2,0.00334591,512
EOD
$ladder9 << EOD
2082.6,0.13141,0.3
2253.1,0.0686563,0.2
2620.8,0.0173372,0.1
5032.7,0.00421046,0.05
EOD
$ladder10 << EOD
2126.1,0.026807,0.3
2387.7,0.0140166,0.2
2655.7,0.00525842,0.1
4729,0.00242811,0.05
EOD
$ladder11 << EOD
67.7,0.14722,2
74.8,0.0772026,4
97.7,0.039225,8
142.7,0.0218311,16
227.7,0.0124875,32
412.3,0.00781045,64
757.1,0.00494012,128
EOD
$ladder12 << EOD
28.3,0.878057,1
46.8,0.824522,2
78.4,0.766667,4
142.7,0.685283,8
274.5,0.578575,16
561.8,0.448926,32
1047.9,0.312494,64
2115.9,0.196795,128
4553.8,0.112961,256
8408.7,0.060354,512
16764.2,0.0323506,1024
34148.3,0.0171026,2048
66609.5,0.00936179,4096
EOD
$ladder13 << EOD
27.7,0.878057,1
42.1,0.824522,2
68.3,0.766667,4
113.3,0.685283,8
321.9,0.578575,16
439.8,0.448926,32
948.4,0.312494,64
1718.6,0.196795,128
3595.9,0.112961,256
7042.1,0.060354,512
13974,0.0323506,1024
28475.5,0.0171026,2048
54711.6,0.00936179,4096
EOD
$ladder14 << EOD
34.4,0.878057,1
37.7,0.824522,2
68.4,0.766667,4
113.4,0.685283,8
213.2,0.578575,16
417.5,0.448926,32
817.4,0.312494,64
1617.4,0.196795,128
3487.7,0.112961,256
6411.6,0.0603539,512
13129.7,0.0323506,1024
26608.8,0.0171026,2048
51683.3,0.00936178,4096
EOD
$ladder15 << EOD
17020.8,0.573624,0.3
15770.6,0.392683,0.2
10055.7,0.138688,0.1
15888.9,0.037798,0.05
34115.4,0.0147089,0.03
46485.3,0.00992075,0.02
49427.4,0.00944025,0.01
52588.7,0.00943577,0.005
51960,0.00943578,0.003
50313.7,0.00943578,0.002
EOD
$ladder16 << EOD
17091.5,0.0489253,0.3
15841.6,0.0264235,0.2
10055.5,0.0111529,0.1
15933.5,0.00480722,0.05
EOD
$ladder17 << EOD
89.3,0.255981,2
124.4,0.143831,4
177.3,0.0854208,8
257.8,0.0507788,16
466.2,0.0323639,32
875.8,0.0222647,64
1811.4,0.01589,128
3289.3,0.0109536,256
6485.6,0.00704428,512
13244,0.00457732,1024
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
