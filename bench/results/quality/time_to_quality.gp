# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
24.1,0.679437,1
41,0.490433,2
75.5,0.278004,4
131.1,0.182895,8
266.2,0.12552,16
500.9,0.093132,32
1016.4,0.0726086,64
1949.4,0.0554774,128
4018.2,0.0397298,256
8278.1,0.0254136,512
16162.7,0.0152031,1024
29831.7,0.00838516,2048
60993,0.00442167,4096
EOD
$ladder1 << EOD
43.7,0.679434,1
38.8,0.492112,2
58.9,0.277622,4
113.9,0.182084,8
182.9,0.125583,16
342.6,0.0930606,32
660.6,0.0726488,64
1455.8,0.0554946,128
2920.4,0.0397952,256
5587.9,0.0254598,512
10756.3,0.015198,1024
19590.3,0.00841318,2048
40474.3,0.00443635,4096
EOD
$ladder2 << EOD
29.7,0.679434,1
34.4,0.492112,2
50.8,0.277622,4
92.2,0.182084,8
162,0.125583,16
285,0.0930606,32
601.4,0.0726488,64
1196.7,0.0554946,128
2480.4,0.0397952,256
4817.8,0.0254598,512
8760.5,0.015198,1024
17698.8,0.00841319,2048
35577.1,0.00443634,4096
EOD
$ladder3 << EOD
232.7,0.22963,0.3
485.6,0.175383,0.2
1620.1,0.0944035,0.1
5645.5,0.0451198,0.05
11683.5,0.0182385,0.03
17522.9,0.00922735,0.02
28747.9,0.00487781,0.01
EOD
$ladder4 << EOD
301.5,0.0938681,0.3
515.3,0.0706154,0.2
1672.8,0.0375167,0.1
5844.4,0.0140491,0.05
11233.9,0.00633448,0.03
17715.8,0.00345756,0.02
EOD
$ladder5 << EOD
97.3,0.164791,2
111.5,0.110123,4
155.6,0.0823699,8
200.8,0.060038,16
349,0.0422856,32
652.1,0.0307448,64
1202.5,0.0190176,128
2623.8,0.0117806,256
4913.2,0.00765495,512
8757.9,0.00494589,1024
EOD
$ladder6 << EOD
18.5,0.526665,1
38.6,0.41816,2
69.9,0.288541,4
111.8,0.165654,8
161.8,0.0932936,16
328.3,0.0470608,32
537.2,0.0243541,64
1102.4,0.0122443,128
2236.3,0.00641035,256
4492.6,0.00330911,512
EOD
$ladder7 << EOD
19.7,0.527655,1
28.3,0.417908,2
54.5,0.287906,4
89.8,0.166686,8
158,0.0935784,16
206.4,0.0484547,32
521.3,0.0243385,64
830.3,0.0119929,128
1455.2,0.00643184,256
3072.7,0.00334591,512
EOD
$ladder8 << EOD
25.7,0.527655,1
33,0.417908,2
46.8,0.287906,4
62.2,0.166686,8
115.6,0.0935784,16
207.6,0.0484547,32
386.9,0.0243385,64
817.1,0.0119929,128
1578.1,0.00643184,256
3175,0.00334591,512
EOD
$ladder9 << EOD
217.5,0.133966,0.3
389.1,0.0709895,0.2
1163.1,0.018023,0.1
3984.1,0.00444991,0.05
EOD
$ladder10 << EOD
259.8,0.0273321,0.3
429.2,0.0144666,0.2
1195.4,0.00537724,0.1
4102.8,0.00249061,0.05
EOD
$ladder11 << EOD
87,0.14722,2
98.8,0.0772026,4
124.8,0.039225,8
168.4,0.0218311,16
267.6,0.0124875,32
457.6,0.00781045,64
877.8,0.00494012,128
EOD
$ladder12 << EOD
23,0.878057,1
49.2,0.824522,2
97.7,0.766667,4
179.8,0.685283,8
288.3,0.578575,16
582.2,0.448926,32
1081.5,0.312494,64
2340.1,0.196795,128
4465.8,0.112961,256
8471.6,0.060354,512
17034.9,0.0323506,1024
34024.1,0.0171026,2048
71726.6,0.00936179,4096
EOD
$ladder13 << EOD
29.2,0.878057,1
49.7,0.824522,2
81.3,0.766667,4
121.7,0.685283,8
245.5,0.578575,16
467.2,0.448926,32
905.9,0.312494,64
1789.7,0.196795,128
3556.5,0.112961,256
7030.2,0.060354,512
14205,0.0323506,1024
28226.3,0.0171026,2048
61230.3,0.00936179,4096
EOD
$ladder14 << EOD
34.6,0.878057,1
48.5,0.824522,2
75.1,0.766667,4
124.2,0.685283,8
229.3,0.578575,16
441.5,0.448926,32
842.9,0.312494,64
1738.2,0.196795,128
3368.3,0.112961,256
6560.8,0.0603539,512
13437.5,0.0323506,1024
26334.5,0.0171026,2048
58919.6,0.00936178,4096
EOD
$ladder15 << EOD
457.2,0.590991,0.3
1001.5,0.414237,0.2
3916.6,0.149617,0.1
14369.5,0.0401272,0.05
33623.4,0.0154627,0.03
47359.2,0.0103426,0.02
48589.9,0.00984314,0.01
50264,0.00983804,0.005
49986.2,0.00983804,0.003
49379.9,0.00983804,0.002
EOD
$ladder16 << EOD
522.1,0.0557539,0.3
1107,0.0281883,0.2
3942.1,0.0115318,0.1
14151.1,0.00497934,0.05
EOD
$ladder17 << EOD
111,0.255981,2
137,0.143831,4
188.8,0.0854208,8
299.7,0.0507788,16
463.7,0.0323639,32
925.8,0.0222647,64
1761.8,0.01589,128
3377.3,0.0109536,256
6651.9,0.00704428,512
13521.1,0.00457732,1024
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
