set terminal pngcairo size 800,500
set output 'voxelization.png'
set title 'Voxelization: time against volume error (labels: resolution)'
set xlabel 'ms (2 threads)'
set ylabel '|relative volume error|'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key left bottom
plot 'voxelization.dat' index 0 using 1:2 with linespoints title 'sphere', '' index 0 using 1:2:3 with labels offset 1,0.7 notitle, '' index 1 using 1:2 with linespoints title 'hourglass', '' index 1 using 1:2:3 with labels offset 1,0.7 notitle, '' index 2 using 1:2 with linespoints title 'torus', '' index 2 using 1:2:3 with labels offset 1,0.7 notitle
