# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
26.7,0.679434,1
44.7,0.492112,2
56.7,0.277622,4
96.5,0.182084,8
187,0.125583,16
356.4,0.0930606,32
711.3,0.0726488,64
1332.9,0.0554946,128
2639.7,0.0397952,256
5421.7,0.0254598,512
10606.9,0.015198,1024
21273,0.00841318,2048
41585.9,0.00443635,4096
EOD
$ladder1 << EOD
25.7,0.679434,1
36.7,0.492112,2
53.8,0.277622,4
94.2,0.182084,8
167.8,0.125583,16
302.7,0.0930606,32
563.5,0.0726488,64
1157.6,0.0554946,128
2348.3,0.0397952,256
4398.5,0.0254598,512
8890.2,0.015198,1024
18055.2,0.00841319,2048
34721,0.00443634,4096
EOD
$ladder2 << EOD
3415.9,0.226553,0.3
5834.5,0.170651,0.2
9193.8,0.0875324,0.1
13738.5,0.0402792,0.05
17508.1,0.0166098,0.03
22428.1,0.00809125,0.02
30529.6,0.00460345,0.01
EOD
$ladder3 << EOD
3208.2,0.09068,0.3
5876.1,0.0687036,0.2
9304.4,0.0311906,0.1
13811.3,0.0120992,0.05
17032.1,0.00560858,0.03
21099.9,0.00325735,0.02
EOD
$ladder4 << EOD
92.9,0.164791,2
144.4,0.110123,4
183.9,0.0823699,8
250.5,0.060038,16
349.9,0.0422856,32
647.4,0.0307448,64
1239.6,0.0190176,128
2371.5,0.0117806,256
4500.1,0.00765495,512
9006.5,0.00494589,1024
EOD
$ladder5 << EOD
18.8,0.527655,1
28,0.417908,2
40.5,0.287906,4
61,0.166686,8
141.6,0.0935784,16
199.7,0.0484547,32
393.3,0.0243385,64
842.4,0.0119929,128
1486.3,0.00643184,256
3075.6,0.00334591,512
EOD
$ladder6 << EOD
22.2,0.527655,1
28.6,0.417908,2
39.3,0.287906,4
62.5,0.166686,8
115.6,0.0935784,16
216.4,0.0484547,32
405.8,0.0243385,64
834.6,0.0119929,128
1542.5,0.00643184,256
3055.7,0.00334591,512
EOD
$ladder7 << EOD
2056.2,0.13141,0.3
2300.8,0.0686563,0.2
2578.9,0.0173372,0.1
5201,0.00421046,0.05
EOD
$ladder8 << EOD
2166.6,0.026807,0.3
2435.2,0.0140166,0.2
2915.1,0.00525842,0.1
5419.3,0.00242811,0.05
EOD
$ladder9 << EOD
87,0.14722,2
121.8,0.0772026,4
157.3,0.039225,8
221.3,0.0218311,16
299.5,0.0124875,32
490.7,0.00781045,64
895.1,0.00494012,128
EOD
$ladder10 << EOD
28.4,0.878057,1
40.9,0.824522,2
61.2,0.766667,4
122.4,0.685283,8
241.7,0.578575,16
516.5,0.448926,32
958.1,0.312494,64
1902.4,0.196795,128
4035.2,0.112961,256
7736.4,0.060354,512
14853.2,0.0323506,1024
30388.3,0.0171026,2048
57318,0.00936179,4096
EOD
$ladder11 << EOD
31.6,0.878057,1
48.1,0.824522,2
63.6,0.766667,4
114.7,0.685283,8
220.5,0.578575,16
442.8,0.448926,32
921.1,0.312494,64
1887.8,0.196795,128
3913.2,0.112961,256
7122.7,0.0603539,512
13612.1,0.0323506,1024
30933.5,0.0171026,2048
53235.8,0.00936178,4096
EOD
$ladder12 << EOD
18661.7,0.573624,0.3
16992.7,0.392683,0.2
10246.4,0.138688,0.1
16439.4,0.037798,0.05
35560.2,0.0147089,0.03
50520.7,0.00992075,0.02
55542.9,0.00944025,0.01
58991.1,0.00943577,0.005
57758.3,0.00943578,0.003
55010.9,0.00943578,0.002
EOD
$ladder13 << EOD
18400.4,0.0489253,0.3
16554.7,0.0264235,0.2
10306.7,0.0111529,0.1
16595.2,0.00480722,0.05
EOD
$ladder14 << EOD
101.9,0.255981,2
133.1,0.143831,4
198.4,0.0854208,8
307.8,0.0507788,16
564,0.0323639,32
989.2,0.0222647,64
2053.3,0.01589,128
3632.7,0.0109536,256
7068.9,0.00704428,512
14257.3,0.00457732,1024
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
