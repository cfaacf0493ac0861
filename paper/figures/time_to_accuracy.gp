# Error against time, from results/time_to_accuracy.csv (written by build/time_to_accuracy): the
# relative distance of max w and of the total contact force to the plate's answer (the rim-contact series, results/rim_answer.csv), against the
# wall time of the whole process (plate, PETSc's SNESVI peer, or gmsh and FreeFem++), one line per
# solver and sampling (n = 8, 16, ...; FreeFEM: 4, 8, ... cells per quarter circle).
# Filled points: certified runs (exit 0); open points: runs that exit 3.
# Usage: gnuplot -e "fmt='svg'; out='results/time_to_accuracy.svg'" paper/figures/time_to_accuracy.gp
# Three panels a row, at most six lines each: this code's exact solver in each space and sampling;
# the peers beside the exact nodal solve they match and the default; the paper's penalty schemes
# beside the default. Max w above, the total force below. Each configuration keeps its colour,
# its marker and its dash in every panel, so that the lines part in greyscale too.
if (fmt eq 'svg') { set terminal svg size 1200,900 dynamic font 'Helvetica,16' } else { set terminal pngcairo size 1200,900 font 'Helvetica,11' }
set output out
set datafile separator ','
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set grid
set linetype 9 lc rgb '#8c564b'
set linetype 10 lc rgb '#17becf'
set linetype 11 lc rgb '#7f7f7f'
set linetype 12 lc rgb '#bcbd22'
set linetype 13 lc rgb '#e377c2'
data = 'results/time_to_accuracy.csv'
stats data using 2 nooutput
blocks = STATS_blocks
# The configurations of src/programs/time_to_accuracy.cpp, in its order (the CSV has one block each).
array names[13] = ["default: edge, kink carried", "edge, plain", "edge points", "edge, whole plate", "nodes", "Gauss", "(3a) edge", "(3a) Gauss (paper)", "(5a) Gauss (paper)", "SNESVI rsls, nodes", "SNESVI ssls, nodes", "FreeFEM HCT, whole", "FreeFEM HCT, quarter"]
# Filled marks only (open ones are the runs that exit 3), distinct within each panel.
array marker[13] = [7, 5, 9, 11, 13, 15, 5, 9, 11, 5, 9, 11, 15]
array dash[13] = [1, 2, 3, 4, 5, 1, 2, 3, 4, 2, 3, 4, 1]
ok(col) = (column(3) == 0 && column(col) > 0) ? column(col) : NaN
bad(col) = (column(3) != 0 && column(col) > 0) ? column(col) : NaN
# Which blocks (1-based configurations) each panel draws.
panel1 = "1 2 3 4 5 6"
panel2 = "1 5 10 11 12 13"
panel3 = "1 7 8 9"
array titles[3] = ["this code, exact", "peers on the same scene", "the paper's penalty schemes"]
set multiplot
# Open marks: runs that exit 3, not certified. The keys go in a strip of their own below the panels,
# one under each column, where they cover no point.
unset key
do for [row = 0:1] {
  col = (row == 0 ? 8 : 9)
  do for [p = 1:3] {
    list = (p == 1 ? panel1 : p == 2 ? panel2 : panel3)
    set origin (p - 1) / 3.0, (row == 0 ? 0.58 : 0.17)
    set size 1 / 3.0, 0.42
    set title (row == 0 ? titles[p] : '')
    set xlabel (row == 1 ? 'wall time (s)' : '')
    set ylabel (p == 1 ? (row == 0 ? 'error in max w' : 'error in the force') : '')
    plot for [k in list] data index (int(k) - 1) using 4:(ok(col)) with linespoints pt marker[int(k)] ps 0.9 dt dash[int(k)] lc int(k) notitle, \
         for [k in list] data index (int(k) - 1) using 4:(bad(col)) with points pt 6 ps 0.9 lc int(k) notitle
  }
}
unset title
unset xlabel
unset ylabel
unset tics
unset border
unset grid
unset logscale
set xrange [0:1]
set yrange [0:1]
set key center top box samplen 2 spacing 0.9
do for [p = 1:3] {
  list = (p == 1 ? panel1 : p == 2 ? panel2 : panel3)
  set origin (p - 1) / 3.0, 0
  set size 1 / 3.0, 0.16
  set tmargin 0
  set bmargin 0
  plot for [k in list] NaN with linespoints pt marker[int(k)] ps 0.9 dt dash[int(k)] lc int(k) title names[int(k)]
}
unset multiplot
