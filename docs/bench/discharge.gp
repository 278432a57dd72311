set terminal pngcairo size 800,400
set output 'discharge.png'
set title 'Hourglass discharge (mean of 10 steps)'
set xlabel 'step'
set ylabel 'grains per step'
set yrange [0:*]
set grid
plot 'discharge.dat' using 1:2 with lines title 'discharge rate'
