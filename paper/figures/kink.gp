# What carrying the kink buys, from results/kink.csv (written by build/kink_study): the relative error
# of max w and of the total force against h, in the plain space (open marks, dashed) and with the
# kink carried (D31; filled marks), on three scenes the rim-contact series solves: max w above, the
# force below; the plain space left, with the slope h^3 dotted, the kink carried right, with h^4. Four
# lines a panel, each scene with its own colour and mark in both spaces.
# Usage: gnuplot -e "fmt='svg'; out='results/kink.svg'" paper/figures/kink.gp   (fmt: svg or png)
if (fmt eq 'svg') { set terminal svg size 1000,760 dynamic font 'Helvetica,14' } else { set terminal pngcairo size 1000,760 font 'Helvetica,11' }
set output out
set datafile separator ','
set logscale xy
set format y '10^{%L}'
set xlabel 'h'
set grid
set key top left opaque box
data = 'results/kink.csv'
pick(scene, space, col) = (strcol(1) eq scene && strcol(2) eq space && column(col) > 0) ? column(col) : NaN
set multiplot layout 2,2
do for [row = 1:2] {
  col = row == 1 ? 8 : 10
  set ylabel row == 1 ? 'relative error in max w' : 'relative error in the force'
  do for [space = 1:2] {
    sp = space == 1 ? 'plain' : 'kink'
    set title row == 1 ? (space == 1 ? 'plain space' : 'kink carried (D31)') : ''
    if (space == 1) {
      plot data using 4:(pick('paper', sp, col)) with linespoints pt 6 dt 2 lc 1 title 'paper', \
           data using 4:(pick('off-centre', sp, col)) with linespoints pt 4 dt 2 lc 2 title 'off-centre', \
           data using 4:(pick('oblong', sp, col)) with linespoints pt 8 dt 2 lc 3 title '1.25 x 1', \
           [0.003:0.07] 0.05 * x**3 with lines dt 3 lc 0 title 'h^3'
    } else {
      plot data using 4:(pick('paper', sp, col)) with linespoints pt 7 lc 1 title 'paper', \
           data using 4:(pick('off-centre', sp, col)) with linespoints pt 5 lc 2 title 'off-centre', \
           data using 4:(pick('oblong', sp, col)) with linespoints pt 9 lc 3 title '1.25 x 1', \
           [0.003:0.07] 0.1 * x**4 with lines dt 3 lc 0 title 'h^4'
    }
  }
}
unset multiplot
