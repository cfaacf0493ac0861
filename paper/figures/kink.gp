# What carrying the kink buys, from results/kink.csv (written by build/kink_study): the relative error
# of max w and of the total force against h, in the plain space (open marks, dashed) and with the
# kink carried (D31; filled marks), on three scenes the rim-contact series solves. Slopes h^3 and h^4
# are dotted.
# Usage: gnuplot -e "fmt='svg'; out='results/kink.svg'" paper/figures/kink.gp   (fmt: svg or png)
if (fmt eq 'svg') { set terminal svg size 1000,430 dynamic font 'Helvetica,14' } else { set terminal pngcairo size 1000,430 font 'Helvetica,11' }
set output out
set datafile separator ','
set logscale xy
set format y '10^{%L}'
set xlabel 'h'
set grid
set key top left opaque box
data = 'results/kink.csv'
pick(scene, space, col) = (strcol(1) eq scene && strcol(2) eq space && column(col) > 0) ? column(col) : NaN
set multiplot layout 1,2
do for [panel = 1:2] {
  col = panel == 1 ? 8 : 10
  set title panel == 1 ? 'max w: relative error against the series' : 'total force: relative error against the series'
  set ylabel 'relative error'
  # The key names the scenes; dashed lines with open marks are the plain space, solid with filled marks the kink carried.
  plot data using 4:(pick('paper', 'plain', col)) with linespoints pt 6 dt 2 lc 1 notitle, \
       data using 4:(pick('paper', 'kink', col)) with linespoints pt 7 lc 1 title 'paper', \
       data using 4:(pick('off-centre', 'plain', col)) with linespoints pt 4 dt 2 lc 2 notitle, \
       data using 4:(pick('off-centre', 'kink', col)) with linespoints pt 5 lc 2 title 'off-centre', \
       data using 4:(pick('oblong', 'plain', col)) with linespoints pt 8 dt 2 lc 3 notitle, \
       data using 4:(pick('oblong', 'kink', col)) with linespoints pt 9 lc 3 title '1.25 x 1', \
       [0.003:0.07] 0.05 * x**3 with lines dt 3 lc 0 title 'h^3', \
       [0.003:0.07] 0.1 * x**4 with lines dt 3 lc 7 title 'h^4'
}
unset multiplot
