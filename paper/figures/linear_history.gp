# The linear scheme's history, from results/linear_history.csv (written by build/contraction): at
# one eps on the paper's grid, the size of each step, the true distance to w_eps and the bound (D7)
# step / (eps lambda_1h), against the iteration. The paper stops when the step falls below OS.
# Usage: gnuplot -e "fmt='svg'; out='results/linear_history.svg'" paper/figures/linear_history.gp
if (fmt eq 'svg') { set terminal svg size 900,500 dynamic font 'Helvetica,16' } else { set terminal pngcairo size 900,500 font 'Helvetica,12' }
set encoding utf8
set output out
set datafile separator ','
set logscale xy
set format y '10^{%L}'
set xlabel 'iteration'
set xrange [0.8:*]  # the first iteration off the frame
set ylabel 'max over the nodes'
set grid
set key bottom left box opaque  # the lower left is empty: every curve falls to the right
data = 'results/linear_history.csv'
plot data using 1:2 with lines lw 2 lc rgb '#1f4e8c' title 'step |w^n − w^{n−1}|', \
     data using 1:3 with lines lw 2 dt 4 lc rgb '#c0392b' title 'true error |w^n − w^{ε}|', \
     data using 1:4 with lines lw 2 dt 2 lc rgb '#2e8b57' title 'bound (D7): step / (ε λ_{1h})'
