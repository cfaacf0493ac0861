# Theorem 2 as a plot, from results/contraction.csv (written by build/contraction): against eps, the
# factor by which the linear scheme (5a) shrinks its steps (no contact, and the slowest with the
# paper's obstacle) and the ratio of the energies of its steps, beside q = 1/(1 + eps lambda_1h),
# q^2 and the paper's rho, on h = 1/16.
# Usage: gnuplot -e "fmt='svg'; out='results/contraction.svg'" paper/figures/contraction.gp
if (fmt eq 'svg') { set terminal svg size 900,500 dynamic font 'Helvetica,16' } else { set terminal pngcairo size 900,500 font 'Helvetica,12' }
set output out
set datafile separator ','
set logscale x
set xlabel 'ε'
set ylabel 'factor per step'
# Headroom above 1, where no factor can be, for the keys.
set yrange [-0.03:1.6]
set ytics 0,0.2,1
# The eps range of the data, read from it, with room so that its end points stay off the frame.
stats 'results/contraction.csv' using 3 nooutput
set xrange [STATS_min / 1.6 : STATS_max * 1.6]
set format x "%g"
set grid
# Two panels, five lines at most in each: the factor of the steps beside q, and the ratio of the
# energies beside q^2, each with the paper's rho, which bounds the energy.
set key inside top right box opaque
data = 'results/contraction.csv'
fine(s, col) = (column(1) == 16 && strcol(2) eq s) ? column(col) : NaN
set multiplot layout 1,2
set title 'steps: the factor per step'
plot data using 3:(fine('nodes', 5)) with lines lw 2 lc rgb '#1f4e8c' title 'q', \
     data using 3:(fine('nodes', 10)) with lines lw 1 dt 3 lc rgb '#c0392b' title "paper's ρ", \
     data using 3:(fine('nodes', 6)) with points pt 6 ps 1.6 lc rgb '#1f4e8c' title 'no contact', \
     data using 3:(fine('nodes', 7)) with points pt 7 ps 1.2 lc rgb '#2e8b57' title 'obstacle, nodes', \
     data using 3:(fine('gauss', 7)) with points pt 5 ps 1.2 lc rgb '#8e44ad' title 'obstacle, Gauss'
set title 'energy: the ratio per step'
set ylabel ''
plot data using 3:(fine('nodes', 8)) with lines lw 2 dt 2 lc rgb '#1f4e8c' title 'q^2', \
     data using 3:(fine('nodes', 10)) with lines lw 1 dt 3 lc rgb '#c0392b' title "paper's ρ", \
     data using 3:(fine('nodes', 9)) with points pt 9 ps 1.4 lc rgb '#d35400' title 'obstacle, nodes', \
     data using 3:(fine('gauss', 9)) with points pt 11 ps 1.4 lc rgb '#7f6000' title 'obstacle, Gauss'
unset multiplot
