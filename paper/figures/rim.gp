# The contact force per unit length along a quarter of the rim, from results/crosscheck_rim.csv
# (written by build/crosscheck): FreeFEM's forces at the circle's vertices over their arcs, this
# code's edge rows (the spline of their multipliers, a function of the angle), and its nodal and
# Gauss samplings binned by angle, each on its finest grid.
# Usage: gnuplot -e "fmt='svg'; out='results/rim.svg'" paper/figures/rim.gp
if (fmt eq 'svg') { set terminal svg size 900,500 dynamic font 'Helvetica,16' } else { set terminal pngcairo size 900,500 font 'Helvetica,12' }
set output out
set datafile separator ','
set xlabel 'angle about the centre of the disk (0: towards the side x = 1)'
set ylabel 'q, force per unit length'
set xrange [-0.04:pi/2 + 0.04]  # room so that the points at 0 and pi/2 stay off the frame
set xtics ('0' 0, 'π/8' pi/8, 'π/4' pi/4, '3π/8' 3*pi/8, 'π/2' pi/2)
set grid
# Inside, above the curves between the binned samplings' end bars: the key covers no data.
set key inside top center horizontal maxcols 2 box opaque
data = 'results/crosscheck_rim.csv'
sel(s) = (strcol(1) eq s) ? column(4) : NaN
plot data using 3:(sel('bfs-nodes')) with histeps lw 1.5 lc rgb '#2e8b57' title 'nodes, binned', \
     data using 3:(sel('bfs-gauss')) with histeps lw 1.5 dt 2 lc rgb '#8e44ad' title 'Gauss, binned', \
     data using 3:(sel('bfs-edge')) with lines lw 2 lc rgb '#1f4e8c' title 'edge rows (spline)', \
     data using 3:(sel('freefem-hct')) with points pt 6 ps 0.9 lc rgb '#c0392b' title 'FreeFEM, circle vertices'
