# Convergence to the continuum answer, from results/continuum_error.csv (written by build/continuum):
# the relative error of max w and of the total contact force against h, for each sampling, measured
# against the rim-contact series (results/rim_answer.csv). Reference slopes h^1 and h^3 are dashed.
# Usage: gnuplot -e "fmt='svg'; out='results/continuum.svg'" paper/figures/continuum.gp   (fmt: svg or png)
if (fmt eq 'svg') { set terminal svg size 1000,430 dynamic font 'Helvetica,14' } else { set terminal pngcairo size 1000,430 font 'Helvetica,11' }
set output out
set datafile separator ','
set logscale xy
set format y '10^{%L}'
set xlabel 'h'
set grid
set key bottom right box opaque
data = 'results/continuum_error.csv'
pick(s, col) = (strcol(1) eq s && column(col) > 0) ? column(col) : NaN
set multiplot layout 1,2
set title 'max w: relative error against the series'
set ylabel 'relative error'
plot data using 3:(pick('edge', 4)) with linespoints pt 7 lc 1 title 'edge (splines)', \
     data using 3:(pick('edge-points', 4)) with linespoints pt 6 dt 2 lc 4 title 'edge (points)', \
     data using 3:(pick('gauss', 4)) with linespoints pt 5 lc 2 title 'Gauss', \
     data using 3:(pick('nodes', 4)) with linespoints pt 9 lc 3 title 'nodes', \
     [0.0015:0.15] 0.1 * x with lines dt 2 lc 0 title 'h', \
     [0.0015:0.15] 0.05 * x**3 with lines dt 3 lc 0 title 'h^3'
set title 'total contact force: relative error against the series'
plot data using 3:(pick('edge', 5)) with linespoints pt 7 lc 1 title 'edge (splines)', \
     data using 3:(pick('edge-points', 5)) with linespoints pt 6 dt 2 lc 4 title 'edge (points)', \
     data using 3:(pick('gauss', 5)) with linespoints pt 5 lc 2 title 'Gauss', \
     data using 3:(pick('nodes', 5)) with linespoints pt 9 lc 3 title 'nodes', \
     [0.0015:0.15] 0.3 * x with lines dt 2 lc 0 title 'h', \
     [0.0015:0.15] 0.3 * x**3 with lines dt 3 lc 0 title 'h^3'
unset multiplot
