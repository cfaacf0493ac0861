# The line load q(theta) on a quarter of the rim (the square's symmetries give the rest), from
# results/continuum_q.csv (written by build/continuum). Left: the rim-contact series, the spline rows'
# q on n = 128 and the point rows' values on the same grid, which scatter. Right: the spline rows'
# distance from the series, over the mean load, on every grid from n = 32: its largest value shrinks with h.
# Usage: gnuplot -e "fmt='svg'; out='results/continuum_q.svg'" paper/figures/continuum_q.gp
if (fmt eq 'svg') { set terminal svg size 1000,430 dynamic font 'Helvetica,14' } else { set terminal pngcairo size 1000,430 font 'Helvetica,11' }
set output out
set datafile separator ','
data = 'results/continuum_q.csv'
set xrange [-0.04:pi/2 + 0.04]  # room so that the points at 0 and pi/2 stay off the frame
set xtics ('0' 0, 'π/8' pi/8, 'π/4' pi/4, '3π/8' 3*pi/8, 'π/2' pi/2)
set xlabel 'angle θ about the centre of the disk'
set grid
is(s, n, col) = (strcol(1) eq s && column(2) == n) ? column(col) : NaN
set multiplot layout 1,2
set title 'q(θ) on n = 128'
set ylabel 'force per unit length'
set yrange [0:50]
# Top centre: q is smallest at pi/4, so the key there covers neither curve nor points.
set key top center box opaque
plot data using 3:(is('edge', 128, 5)) with lines lw 3 lc rgb '#bbbbbb' title 'series', \
     data using 3:(is('edge-points', 128, 4)) with points pt 7 ps 0.6 lc 2 title 'point rows', \
     data using 3:(is('edge', 128, 4)) with lines lw 1.5 lc 1 title 'spline rows'
set title 'spline rows: |q − q_{series}| / mean'
set ylabel ''
set logscale y
set format y '10^{%L}'
set yrange [1e-9:1e2]
set key top center horizontal maxcols 5 box opaque
# A dash per grid, so that the lines part in greyscale too.
grids = '32 64 128 256 512'
plot for [k = 1:words(grids)] data using 3:(is('edge', word(grids, k) + 0, 6)) with lines lw 1.5 dt k title 'n = '.word(grids, k)
unset multiplot
