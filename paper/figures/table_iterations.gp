# The paper's table as a plot, from results/crosscheck_penalty_table.csv (written by
# build/crosscheck_penalty, which gathers the published counts, ours from results/table.csv and
# FreeFEM's): iterations of the linear scheme (5a) against the stopping tolerance OS.
# Usage: gnuplot -e "fmt='svg'; out='results/table_iterations.svg'" paper/figures/table_iterations.gp
if (fmt eq 'svg') { set terminal svg size 900,480 dynamic font 'Helvetica,15' } else { set terminal pngcairo size 900,480 font 'Helvetica,12' }
set output out
set datafile separator ','
set logscale xy
# Tighter tolerances to the right, as a reader follows the table down.
set xrange [2e-4:4e-7] reverse
set yrange [30:3000]
set format x '10^{%L}'
set xlabel 'stopping tolerance OS'
set ylabel '(5a) iterations, all ε levels'
set grid
set key outside right center box
data = 'results/crosscheck_penalty_table.csv'
# -1 marks a FreeFEM run that did not converge: left out rather than drawn at the axis.
ok(col) = column(col) > 0 ? column(col) : NaN
plot data using 1:2 with linespoints pt 7 ps 1.3 lw 2 lc rgb '#000000' title 'the paper', \
     data using 1:3 with linespoints pt 6 ps 1.3 lw 1 dt 2 lc rgb '#555555' title 'GLT', \
     data using 1:4 with linespoints pt 5 ps 1.1 lw 2 lc rgb '#1f4e8c' title 'ours, nodes', \
     data using 1:5 with linespoints pt 4 ps 1.1 lw 2 lc rgb '#8e44ad' title 'ours, Gauss', \
     data using 1:(ok(6)) with linespoints pt 9 ps 1.3 lw 1 lc rgb '#d35400' title 'FreeFEM, 4 cells', \
     data using 1:(ok(7)) with linespoints pt 11 ps 1.3 lw 1 lc rgb '#2e8b57' title 'FreeFEM, 8 cells'
