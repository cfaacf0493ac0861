# Fig. 2 twice: max|w|, max|m12| and the total contact force against the obstacle height R, from
# FreeFEM's penalty script (points) and from this code (lines), both read from
# results/crosscheck_penalty_fig2.csv (written by build/crosscheck_penalty). Scaled to share the axis.
# Usage: gnuplot -e "fmt='svg'; out='results/crosscheck_penalty_fig2.svg'" paper/figures/crosscheck_penalty_fig2.gp
if (fmt eq 'svg') { set terminal svg size 640,430 dynamic font 'Helvetica,14' } else { set terminal pngcairo size 640,430 font 'Helvetica,11' }
set output out
set datafile separator ','
# Top left, in headroom above the lines (they all rise from the origin): the key covers none of them.
set key top left box opaque
set xlabel 'obstacle height R'
set ylabel 'value, scaled as in the key'
set grid
set xrange [0:*]
# Room beyond the last point and above the highest, so that none sits on the frame.
set offsets 0, graph 0.06, graph 0.35, 0
set yrange [0:*]
data = 'results/crosscheck_penalty_fig2.csv'
# columns: R, freefem max_w, max_m12, force, ours max_w, max_m12, force
# One key entry per quantity (this code's line), and one that says what the marks are: each
# quantity has its own dash and mark, so the lines part in greyscale too.
plot data using 1:($5 * 100) with lines lc 3 dt 1 title 'max|w| × 10^2', \
     data using 1:($2 * 100) with points pt 2 ps 1.3 lc 3 notitle, \
     data using 1:($6 * 10) with lines lc 2 dt 2 title 'max|m_{12}| × 10', \
     data using 1:($3 * 10) with points pt 6 ps 1.3 lc 2 notitle, \
     data using 1:($7 * 0.1) with lines lc 4 dt 4 title 'total force × 10^{-1}', \
     data using 1:($4 * 0.1) with points pt 4 ps 1.3 lc 4 notitle, \
     NaN with points pt 1 ps 0 lc rgb 'white' title 'lines: this code; marks: FreeFEM'
