# The line load q(theta) on the rim, from results/continuum_q.csv (written by build/continuum): the
# multiplier at each rim point per unit length, edge sampling, on a quarter of the circle (the
# square's symmetries give the rest), with the code's own fit a0 + a1 cos 4 theta + a2 cos 8 theta +
# a3 cos 12 theta on the finest grid (column 4), so that the plot shows the fit the report uses.
# Usage: gnuplot -e "fmt='svg'; out='results/continuum_q.svg'" paper/figures/continuum_q.gp
if (fmt eq 'svg') { set terminal svg size 900,480 dynamic font 'Helvetica,13' } else { set terminal pngcairo size 900,480 font 'Helvetica,11' }
set output out
set datafile separator ','
set xlabel 'angle theta about the centre of the disk (0: towards the side x = 1)'
set ylabel 'q, force per unit length'
set xrange [0:pi/2]
set xtics ('0' 0, 'pi/8' pi/8, 'pi/4' pi/4, '3pi/8' 3*pi/8, 'pi/2' pi/2)
set grid
set key outside bottom center horizontal box
set fit quiet logfile '/dev/null'
data = 'results/continuum_q.csv'
stats data using 1 nooutput
finest = int(STATS_max)
coarsest = int(STATS_min)
nblocks = STATS_blocks
fine(col) = (column(1) == finest) ? column(col) : NaN
plot for [b = 0:nblocks - 1] data index b using 2:3 with points pt 7 ps 0.5 title sprintf('n = %d', coarsest * 2**b), \
     data using 2:(fine(4)) with lines lw 2 lc 0 title sprintf('fit sum a_k cos 4k theta on n = %d', finest)
