# Fig. 2 twice: max|w|, max|m12| and the total contact force against the obstacle height R, from
# FreeFEM's penalty script (points) and from this code (lines), both read from
# results/crosscheck_penalty_fig2.csv (written by build/crosscheck_penalty). Scaled to share the axis.
# Usage: gnuplot -e "fmt='svg'; out='results/crosscheck_penalty_fig2.svg'" paper/figures/crosscheck_penalty_fig2.gp
if (fmt eq 'svg') { set terminal svg size 640,430 dynamic font 'Helvetica,16' } else { set terminal pngcairo size 640,430 font 'Helvetica,11' }
set output out
set datafile separator ','
# Top left, in headroom above the lines (they all rise from the origin): the key covers none of them.
set key top left box opaque
set xlabel 'obstacle height R'
set ylabel 'value, scaled as in the key'
set grid
# Room beyond the last point and above the highest, so that none sits on the frame.
set offsets 0, 0, graph 0.45, 0
set yrange [0:*]
data = 'results/crosscheck_penalty_fig2.csv'
# The axis ends just past the largest height, not at the next round tick.
stats data using 1 nooutput
set xrange [0:STATS_max * 1.05]
# columns: R, freefem max_w, max_m12, force, ours max_w, max_m12, force
# One key entry per quantity (this code's line), and one that says what the marks are: each
# quantity has its own dash and mark, so the lines part in greyscale too.
plot data using 1:($5 * 100) with lines lc rgb '#1f4e8c' lw 2 dt 1 notitle, \
     data using 1:($2 * 100) with points pt 2 ps 1.3 lc rgb '#1f4e8c' notitle, \
     data using 1:($6 * 10) with lines lc rgb '#2e8b57' lw 2 dt 2 notitle, \
     data using 1:($3 * 10) with points pt 6 ps 1.3 lc rgb '#2e8b57' notitle, \
     data using 1:($7 * 0.1) with lines lc rgb '#c0392b' lw 2 dt 4 notitle, \
     data using 1:($4 * 0.1) with points pt 4 ps 1.3 lc rgb '#c0392b' notitle, \
     NaN with linespoints lc rgb '#1f4e8c' lw 2 dt 1 pt 2 ps 1.3 title 'max|w| × 10^2', \
     NaN with linespoints lc rgb '#2e8b57' lw 2 dt 2 pt 6 ps 1.3 title 'max|m_{12}| × 10', \
     NaN with linespoints lc rgb '#c0392b' lw 2 dt 4 pt 4 ps 1.3 title 'total force × 10^{-1}', \
     NaN with points pt 1 ps 0 lc rgb 'white' title 'lines: this code; marks: FreeFEM'
