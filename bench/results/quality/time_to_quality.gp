# SPDX-License-Identifier: Apache-2.0
# Time to quality: 1 - SSIM against a long reference render over render time, one line
# per configuration (written by fgr bench quality).
set terminal pngcairo size 1680,520 font 'sans,10'
set output 'time_to_quality.png'
set datafile separator ','
$ladder0 << EOD
16.4,0.679765,1
18.6,0.492519,2
52.4,0.278875,4
116.6,0.183732,8
200.4,0.127596,16
353.6,0.0955823,32
702.9,0.0754103,64
1126,0.0579953,128
2282.8,0.042458,256
4531.3,0.0283342,512
8449.2,0.0181197,1024
EOD
$ladder1 << EOD
15.8,0.679765,1
27.8,0.492519,2
33.4,0.278875,4
59.4,0.183732,8
111.9,0.127596,16
233.5,0.0955823,32
481.2,0.0754103,64
1020.2,0.0579953,128
1828.5,0.042458,256
3604.5,0.0283342,512
6918.5,0.0181197,1024
EOD
$ladder2 << EOD
827.4,0.228287,0.3
1460.3,0.173254,0.2
2447.3,0.0912575,0.1
3533.3,0.0451548,0.05
5138.7,0.0240673,0.03
6361.8,0.0181515,0.02
6875.1,0.0175929,0.01
6839.4,0.0176032,0.005
EOD
$ladder3 << EOD
869.7,0.0795193,0.3
1500.2,0.0600907,0.2
2428.1,0.0398678,0.1
3658.4,0.0221209,0.05
5241.6,0.0136879,0.03
6440.8,0.0111863,0.02
6964.3,0.0109928,0.01
6803.2,0.0110036,0.005
EOD
$ladder4 << EOD
51.3,0.165145,2
71.8,0.101194,4
99.3,0.0679342,8
154.6,0.0518046,16
263.8,0.0405774,32
539.6,0.031981,64
1039.5,0.0240599,128
1873.9,0.0176736,256
3640,0.0132581,512
6930.4,0.0099299,1024
EOD
$ladder5 << EOD
11.8,0.52766,1
17.3,0.417912,2
35.4,0.287905,4
64.2,0.166687,8
107,0.0935725,16
235.4,0.048457,32
334.8,0.0243405,64
711.1,0.0119928,128
1245.2,0.00643217,256
2370.2,0.00334668,512
4839.9,0.00186226,1024
EOD
$ladder6 << EOD
13.4,0.52766,1
23.3,0.417912,2
25.9,0.287905,4
49.7,0.166687,8
75.6,0.0935725,16
223.6,0.048457,32
447.7,0.0243405,64
671.3,0.0119928,128
1259.2,0.00643217,256
2603.3,0.00334668,512
4600.1,0.00186226,1024
EOD
$ladder7 << EOD
703.2,0.131452,0.3
847.1,0.0686282,0.2
1281.8,0.017387,0.1
2661.4,0.00438441,0.05
3917.6,0.00236418,0.03
4226.6,0.00211536,0.02
4244.6,0.00211349,0.01
4245.2,0.00211138,0.005
EOD
$ladder8 << EOD
756.8,0.0637385,0.3
895.5,0.0314552,0.2
1373.2,0.0094749,0.1
2757.7,0.00348819,0.05
4140.1,0.00214692,0.03
4566.2,0.00197592,0.02
4416.3,0.001959,0.01
4511.9,0.00195478,0.005
EOD
$ladder9 << EOD
41.7,0.279112,2
61.8,0.170509,4
68,0.0896353,8
116.6,0.0490765,16
1051.9,0.0255643,32
384.2,0.0141879,64
832.4,0.00810842,128
1323.8,0.00519824,256
2675.5,0.00306756,512
4843.1,0.00175078,1024
EOD
$ladder10 << EOD
22.6,0.87766,1
41.3,0.824147,2
75.3,0.766849,4
136.4,0.68529,8
178.6,0.5786,16
505.2,0.449303,32
778.8,0.314112,64
1641.3,0.20025,128
3026.2,0.118075,256
6241.4,0.0666225,512
11525.3,0.0387367,1024
EOD
$ladder11 << EOD
16.4,0.87766,1
27.1,0.824147,2
47.6,0.766849,4
90.7,0.68529,8
172.3,0.5786,16
326,0.449303,32
671.8,0.314112,64
1378.8,0.20025,128
2629.5,0.118075,256
5123.1,0.0666225,512
10052,0.0387367,1024
EOD
$ladder12 << EOD
3977.5,0.57338,0.3
4160.3,0.393788,0.2
4482.5,0.144397,0.1
8654.7,0.0480476,0.05
9838.6,0.0402506,0.03
10011.7,0.040055,0.02
10562.6,0.0400273,0.01
10345.1,0.0400273,0.005
EOD
$ladder13 << EOD
4034.1,0.061287,0.3
4249.6,0.0368901,0.2
4417.1,0.0195966,0.1
8677.9,0.0131014,0.05
9913,0.0123691,0.03
10271.8,0.0121728,0.02
10567.3,0.0121394,0.01
10344.2,0.0121394,0.005
EOD
$ladder14 << EOD
74.3,0.260158,2
90.5,0.154379,4
127.9,0.100997,8
192.9,0.0656554,16
371.3,0.0454257,32
691.4,0.0333683,64
1388.4,0.025481,128
2618,0.0193911,256
5176.3,0.0149514,512
9936,0.012717,1024
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
