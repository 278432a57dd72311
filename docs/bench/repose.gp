set terminal pngcairo size 800,500
set output 'repose.png'
set title 'Poured cones: angle in 16 directions'
set xlabel 'direction out of the peak (deg)'
set ylabel 'angle (deg)'
set yrange [0:*]
set grid
set key right top
plot 'repose.dat' index 0 using 1:2 with linespoints title 'asked 25 deg', '' index 1 using 1:2 with linespoints title 'asked 33 deg', '' index 2 using 1:2 with linespoints title 'asked 40 deg'
