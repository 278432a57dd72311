set terminal pngcairo size 800,500
set output 'necks.png'
set title 'Discharge over the drain (mean of 20 steps)'
set xlabel 'share of the sand drained'
set ylabel 'grains per step'
set yrange [0:*]
set grid
set key right top
plot 'necks.dat' index 0 using 1:2 with linespoints title 'neck 4 across', '' index 1 using 1:2 with linespoints title 'neck 6 across', '' index 2 using 1:2 with linespoints title 'neck 8 across', '' index 3 using 1:2 with linespoints title 'neck 12 across', '' index 4 using 1:2 with linespoints title 'neck 16 across'
