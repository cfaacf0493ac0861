# Fig. 2 of the paper, redrawn from results/fig2.csv (written by build/fig2): max|ξ|, max|m12| and
# max|w| at the nodes against the obstacle height R, each with its least-squares line through the
# origin. Each quantity is scaled to share the axis; the slopes in the key are unscaled.
# Usage: gnuplot -e "fmt='svg'; out='results/fig2.svg'" paper/figures/fig2.gp   (fmt: svg or png)
if (fmt eq 'svg') { set terminal svg size 1000,430 dynamic font 'Helvetica,14' } else { set terminal pngcairo size 1000,430 font 'Helvetica,11' }
set output out
set datafile separator ','
# Top left, in headroom kept free above the lines (they all rise from the origin): the key covers no point.
set key top left box opaque samplen 2
set offsets 0, graph 0.04, graph 0.4, 0
set xlabel 'obstacle height R'
set ylabel 'scaled as in the key'
set grid
set xrange [0:*]
set yrange [0:*]
set fit quiet logfile '/dev/null'
data = 'results/fig2.csv'
stats data using 1 nooutput
fine = int(STATS_max)
pick(n, col) = (column(1) == n && strcol(2) eq 'nodes') ? column(col) : NaN
set multiplot layout 1,2

n = 4
s1 = 1e-2; s2 = 10; s3 = 100
a1 = 1; a2 = 1; a3 = 1
fit a1*x data using 3:(pick(n, 4)) via a1
fit a2*x data using 3:(pick(n, 5)) via a2
fit a3*x data using 3:(pick(n, 6)) via a3
set title 'h = 1/4 as in the paper (nodal sampling)'
plot data using 3:(pick(n, 4) * s1) with points pt 2 ps 1.3 lc 1 title sprintf('1: max|ξ| × 10^{-2}   slope %.6g', a1), \
     a1 * s1 * x with lines lc 1 notitle, \
     data using 3:(pick(n, 5) * s2) with points pt 6 ps 1.3 lc 2 title sprintf('2: max|m_{12}| × 10   slope %.6g', a2), \
     a2 * s2 * x with lines lc 2 notitle, \
     data using 3:(pick(n, 6) * s3) with points pt 8 ps 1.3 lc 3 title sprintf('3: max|w| × 10^2   slope %.6g', a3), \
     a3 * s3 * x with lines lc 3 notitle

n = fine
s1 = 1e-4; s4 = 0.1
fit a1*x data using 3:(pick(n, 4)) via a1
fit a2*x data using 3:(pick(n, 5)) via a2
fit a3*x data using 3:(pick(n, 6)) via a3
a4 = 1
fit a4*x data using 3:(pick(n, 7)) via a4
set title sprintf('h = 1/%d (nodal sampling), and the total contact force', fine)
plot data using 3:(pick(n, 4) * s1) with points pt 2 ps 1.3 lc 1 title sprintf('1: max|ξ| × 10^{-4}   slope %.6g', a1), \
     a1 * s1 * x with lines lc 1 notitle, \
     data using 3:(pick(n, 5) * s2) with points pt 6 ps 1.3 lc 2 title sprintf('2: max|m_{12}| × 10   slope %.6g', a2), \
     a2 * s2 * x with lines lc 2 notitle, \
     data using 3:(pick(n, 6) * s3) with points pt 8 ps 1.3 lc 3 title sprintf('3: max|w| × 10^2   slope %.6g', a3), \
     a3 * s3 * x with lines lc 3 notitle, \
     data using 3:(pick(n, 7) * s4) with points pt 4 ps 1.3 lc 4 title sprintf('total force × 10^{-1}   slope %.6g', a4), \
     a4 * s4 * x with lines lc 4 notitle
unset multiplot
