set terminal pngcairo size 800,500
set output 'repose.png'
set title 'Poured cones: the 16 direction sectors of each cone'
set xlabel 'direction out of the peak (deg)'
set ylabel 'angle (deg)'
set yrange [0:*]
set grid
set key right top
plot 'repose.dat' index 0 using 1:2 with linespoints title 'asked 25, seed 1', '' index 1 using 1:2 with linespoints title 'asked 33, seed 1', '' index 2 using 1:2 with linespoints title 'asked 40, seed 1'
