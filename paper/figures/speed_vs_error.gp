# Work-precision, from results/speed_vs_error.csv (written by build/bench, `make bench`).
# Left: error in the centre deflection against the continuum answer's max w (continuum_limits.csv), versus solve time; labels give the
# cells n per side, and the exact solver's line is the discretisation error alone. Right: each
# obstacle solve's time as a multiple of one unconstrained factorisation and solve on its grid.
# Usage: gnuplot -e "fmt='svg'; out='results/speed_vs_error.svg'" paper/figures/speed_vs_error.gp
if (fmt eq 'svg') { set terminal svg size 1100,480 dynamic font 'Helvetica,15' } else { set terminal pngcairo size 1100,480 font 'Helvetica,11' }
set output out
set datafile separator ','
set grid
data = 'results/speed_vs_error.csv'
# Columns: 1 solver, 2 n, 4 tol, 9 seconds, 10 ratio, 14 error_limit.
# Columns: 5 converged. A run that stopped without meeting its tolerance has no certified answer: it
# is drawn apart, as a grey cross, not on its scheme's line.
sel(s, t, col) = (strcol(1) eq s && (t eq '' || strcol(4) eq t) && strcol(5) eq 'yes') ? column(col) : NaN
failed(col) = ((strcol(1) eq 'linear' || strcol(1) eq 'nonlinear') && strcol(5) ne 'yes') ? column(col) : NaN
# A series with no converged run has nothing on its line: its key entry is left out (an empty title).
undefine STATS_*
stats data using (sel('nonlinear', '1e-08', 9)) nooutput
n3a8 = exists('STATS_records') ? STATS_records : 0
undefine STATS_*
stats data using (sel('linear', '1e-06', 9)) nooutput
n5a6 = exists('STATS_records') ? STATS_records : 0
t3a8 = n3a8 > 0 ? 'scheme (3a), tol 1e-8' : ''
t5a6 = n5a6 > 0 ? 'scheme (5a), tol 1e-6' : ''
set multiplot layout 1,2
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'solve time [s] (fine-grid assembly excluded)'
set ylabel '|w_h(0.5,0.5) − max w of the continuum|'
set key bottom left box opaque 
set title 'error against time'
plot data using (sel('exact', '', 9)):(sel('exact', '', 14)) with linespoints pt 7 lw 2 lc 1 title 'exact constraint', \
     data using (sel('exact', '', 9)):(sel('exact', '', 14)):2 with labels offset 0,1  notitle, \
     data using (sel('nonlinear', '1e-06', 9)):(sel('nonlinear', '1e-06', 14)) with linespoints pt 5 lc 2 title 'scheme (3a), tol 1e-6', \
     data using (sel('nonlinear', '1e-08', 9)):(sel('nonlinear', '1e-08', 14)) with linespoints pt 4 lc 3 title t3a8, \
     data using (sel('linear', '1e-06', 9)):(sel('linear', '1e-06', 14)) with linespoints pt 9 lc 4 title t5a6, \
     data using (failed(9)):(failed(14)) with points pt 2 ps 1.2 lc rgb '#888888' title 'penalty run, not converged'
set logscale x 2
set format x '%g'
set format y '%g'
set xlabel 'cells per side n'
set offsets graph 0.04, graph 0.04, 0, 0  # the first and last grids off the frame
set ylabel 'time / (one factorisation + solve)'
# Room above the highest point for the key, so that it covers none.
set yrange [1:1000]
set key top right box opaque 
set title 'cost in factorisations'
plot data using (sel('exact', '', 2)):(sel('exact', '', 10)) with linespoints pt 7 lw 2 lc 1 title 'exact constraint', \
     data using (sel('nonlinear', '1e-06', 2)):(sel('nonlinear', '1e-06', 10)) with linespoints pt 5 lc 2 title 'scheme (3a), tol 1e-6', \
     data using (sel('nonlinear', '1e-08', 2)):(sel('nonlinear', '1e-08', 10)) with linespoints pt 4 lc 3 title t3a8, \
     data using (sel('linear', '1e-06', 2)):(sel('linear', '1e-06', 10)) with linespoints pt 9 lc 4 title t5a6, \
     data using (failed(2)):(failed(10)) with points pt 2 ps 1.2 lc rgb '#888888' title 'penalty run, not converged'
unset multiplot
