# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
21,0.679434,1
46.6,0.492112,2
59.8,0.277622,4
120.1,0.182084,8
228.3,0.125583,16
365.9,0.0930606,32
696.3,0.0726488,64
1363.8,0.0554946,128
2518.5,0.0397952,256
4954.1,0.0254598,512
9720.4,0.015198,1024
19423.7,0.00841318,2048
38651.2,0.00443635,4096
EOD
$ladder1 << EOD
31.5,0.679434,1
34,0.492112,2
54.3,0.277622,4
96.8,0.182084,8
170.1,0.125583,16
299.8,0.0930606,32
548.7,0.0726488,64
1220.2,0.0554946,128
2249.8,0.0397952,256
4438.2,0.0254598,512
8470.8,0.015198,1024
18061.4,0.00841319,2048
35739.5,0.00443634,4096
EOD
$ladder2 << EOD
3235.2,0.226553,0.3
6284.6,0.170651,0.2
9547.2,0.0875324,0.1
13396.7,0.0402792,0.05
17506.8,0.0166098,0.03
20235.2,0.00809125,0.02
29005.4,0.00460345,0.01
EOD
$ladder3 << EOD
3416.7,0.09068,0.3
5662.9,0.0687036,0.2
9596,0.0311906,0.1
13776.8,0.0120992,0.05
16372.7,0.00560858,0.03
20707.4,0.00325735,0.02
EOD
$ladder4 << EOD
119.8,0.164791,2
147.4,0.110123,4
168.9,0.0823699,8
218.6,0.060038,16
334.5,0.0422856,32
694,0.0307448,64
1264.2,0.0190176,128
2322.4,0.0117806,256
4581.1,0.00765495,512
8478.2,0.00494589,1024
EOD
$ladder5 << EOD
15.7,0.527655,1
22.2,0.417908,2
43.2,0.287906,4
54.7,0.166686,8
145.8,0.0935784,16
1552.4,0.0484547,32
395.9,0.0243385,64
879.4,0.0119929,128
1569.2,0.00643184,256
2822.7,0.00334591,512
EOD
$ladder6 << EOD
22.6,0.527655,1
29.3,0.417908,2
40.7,0.287906,4
69.4,0.166686,8
119.3,0.0935784,16
294.5,0.0484547,32
459.2,0.0243385,64
955.1,0.0119929,128
1722.1,0.00643184,256
3351.2,0.00334591,512
EOD
$ladder7 << EOD
2207.6,0.13141,0.3
2445,0.0686563,0.2
2698.3,0.0173372,0.1
5704.1,0.00421046,0.05
EOD
$ladder8 << EOD
2324.7,0.026807,0.3
2563,0.0140166,0.2
2799.5,0.00525842,0.1
5866.5,0.00242811,0.05
EOD
$ladder9 << EOD
92.4,0.14722,2
97,0.0772026,4
147,0.039225,8
206.1,0.0218311,16
406.6,0.0124875,32
521.1,0.00781045,64
1086.6,0.00494012,128
EOD
$ladder10 << EOD
16.2,0.878057,1
44.3,0.824522,2
87.3,0.766667,4
122.9,0.685283,8
237.5,0.578575,16
496.8,0.448926,32
944.7,0.312494,64
1813.5,0.196795,128
3590.3,0.112961,256
6853.5,0.060354,512
13905.4,0.0323506,1024
29578.2,0.0171026,2048
58664.6,0.00936179,4096
EOD
$ladder11 << EOD
32.9,0.878057,1
47.3,0.824522,2
65.4,0.766667,4
130.1,0.685283,8
240.6,0.578575,16
464,0.448926,32
928.8,0.312494,64
2883,0.196795,128
3366.7,0.112961,256
6644.7,0.0603539,512
13572,0.0323506,1024
28581,0.0171026,2048
58428.4,0.00936178,4096
EOD
$ladder12 << EOD
18780.5,0.573624,0.3
17552.7,0.392683,0.2
11111.6,0.138688,0.1
17374.1,0.037798,0.05
37604.4,0.0147089,0.03
49940.9,0.00992075,0.02
52663.9,0.00944025,0.01
52591.7,0.00943577,0.005
51916.8,0.00943578,0.003
51681.3,0.00943578,0.002
EOD
$ladder13 << EOD
18994.7,0.0489253,0.3
17613.7,0.0264235,0.2
11224.4,0.0111529,0.1
17181.5,0.00480722,0.05
EOD
$ladder14 << EOD
114.1,0.255981,2
145.7,0.143831,4
198.4,0.0854208,8
271.5,0.0507788,16
540.4,0.0323639,32
952.8,0.0222647,64
1864.8,0.01589,128
3395.9,0.0109536,256
6823.3,0.00704428,512
14253.4,0.00457732,1024
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
