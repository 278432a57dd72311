set terminal pngcairo size 800,500
set output 'beverloo.png'
set title 'Discharge against neck diameter'
set xlabel 'D - 1.5 (cells)'
set ylabel 'grains per step'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key left top
plot 'beverloo.dat' index 0 using 1:2 with linespoints title 'measured', '' index 1 using 1:2 with linespoints title 'C sqrt(g) (D - 1.5)^2.5'
