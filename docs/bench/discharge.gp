set terminal pngcairo size 800,500
set output 'discharge.png'
set title 'Hourglass discharge (mean of 10 steps)'
set xlabel 'step'
set ylabel 'grains per step'
set yrange [0:*]
set grid
set key right top
plot 'discharge.dat' index 0 using 1:2 with linespoints title 'discharge rate'
