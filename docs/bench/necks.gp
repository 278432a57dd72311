set terminal pngcairo size 800,500
set output 'necks.png'
set title 'Discharge over the drain (mean of 10 steps)'
set xlabel 'share of the sand drained'
set ylabel 'grains per step'
set yrange [0:*]
set grid
set key right top
plot 'necks.dat' index 0 using 1:2 with linespoints title 'neck radius 2', '' index 1 using 1:2 with linespoints title 'neck radius 2', '' index 2 using 1:2 with linespoints title 'neck radius 3', '' index 3 using 1:2 with linespoints title 'neck radius 4'
