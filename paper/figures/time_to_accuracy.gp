# Error against time, from results/time_to_accuracy.csv (written by build/time_to_accuracy): the
# relative distance of max w and of the total contact force to the plate's answer (the rim-contact series, results/rim_answer.csv), against the
# wall time of the whole process (plate, PETSc's SNESVI peer, or gmsh and FreeFem++), one line per
# solver and sampling (n = 8, 16, ...; FreeFEM: 4, 8, ... cells per quarter circle).
# Filled points: certified runs (exit 0); open points: runs that exit 3.
# Usage: gnuplot -e "fmt='svg'; out='results/time_to_accuracy.svg'" paper/figures/time_to_accuracy.gp
if (fmt eq 'svg') { set terminal svg size 1000,600 dynamic font 'Helvetica,13' } else { set terminal pngcairo size 1000,600 font 'Helvetica,11' }
set output out
set datafile separator ','
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set xlabel 'wall time of the whole process (s)'
set ylabel 'relative error against the series'
set grid
# One key for both panels, drawn as a plot of its own in the strip below them.
set tmargin at screen 0.93
set bmargin at screen 0.36
unset key
# Twelve lines: the default list of colours has eight.
set linetype 9 lc rgb '#8c564b' pt 5
set linetype 10 lc rgb '#17becf' pt 5
set linetype 11 lc rgb '#7f7f7f' pt 5
set linetype 12 lc rgb '#bcbd22' pt 5
data = 'results/time_to_accuracy.csv'
stats data using 2 nooutput
blocks = STATS_blocks
# The configurations of src/programs/time_to_accuracy.cpp, in its order (the CSV has one block each).
array names[12] = ["exact edge kink carried (default)", "exact edge plain", "exact edge points", "exact edge whole plate", "exact nodes", "exact Gauss", "(3a) edge", "(3a) Gauss (paper)", "(5a) Gauss (paper)", "SNESVI rsls nodes", "SNESVI ssls nodes", "FreeFEM HCT vertices"]
ok(col) = (column(3) == 0 && column(col) > 0) ? column(col) : NaN
bad(col) = (column(3) != 0 && column(col) > 0) ? column(col) : NaN
set multiplot
do for [c in "8 9"] {
  set origin (c eq "8" ? 0 : 0.5), 0
  set size 0.5, 1
  set title (c eq "8" ? 'max w' : 'total contact force')
  plot for [b = 0:blocks - 1] data index b using 4:(ok(int(c))) with linespoints pt 7 lc b + 1 notitle, \
       for [b = 0:blocks - 1] data index b using 4:(bad(int(c))) with points pt 6 lc b + 1 notitle
}
set origin 0, 0
set size 1, 0.26
set tmargin 0
set bmargin 0
unset title
unset xlabel
unset ylabel
unset tics
unset border
unset grid
unset logscale
set xrange [0:1]
set yrange [0:1]
set key center center horizontal maxcols 3 box font ',10'
plot for [b = 0:blocks - 1] NaN with linespoints pt 7 lc b + 1 title names[b + 1], \
     NaN with points pt 6 lc rgb '#444444' title 'open: run not certified (exit 3)'
unset multiplot
