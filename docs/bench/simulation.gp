set terminal pngcairo size 800,500
set output 'simulation.png'
set title 'Hourglass drain: median ms per step'
set xlabel 'resolution (cells)'
set ylabel 'ms per step'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key left top
plot 'simulation.dat' index 0 using 1:2 with linespoints title 'sleeping, 1 thread', '' index 1 using 1:2 with linespoints title 'sleeping, 2 threads', '' index 2 using 1:2 with linespoints title 'full sweep, 1 thread', '' index 3 using 1:2 with linespoints title 'full sweep, 2 threads'
