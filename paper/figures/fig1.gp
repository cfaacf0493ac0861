# Fig. 1: (a) the domain, the obstacle disk, the paper's h = 1/4 grid and the check points
# (results/fig1_points.csv); (b) the computed deflection (results/fig1_surface.dat) with the
# sample points where the plate rests on the obstacle (results/fig1_contact.dat). Written by build/fig1.
# Usage: gnuplot -e "fmt='svg'; out='results/fig1.svg'" paper/figures/fig1.gp   (fmt: svg or png)
# Three panels side by side, the height of one: printed across the column (717 px at most), a
# square figure would be held to the print style's 8 cm and shrink its labels below 7 pt. The key of
# (a) is the caption's; (a) and (b) tick only 0, 1/2 and 1.
if (fmt eq 'svg') { set terminal svg size 1300,480 dynamic font 'Helvetica,18' } else { set terminal pngcairo size 1300,480 font 'Helvetica,13' }
set output out
set multiplot

set title '(a) grid h = 1/4, disk, check points'
set origin 0, 0
set size ratio -1 0.32, 1
set xrange [-0.05:1.05]
set yrange [-0.05:1.05]
set xtics 0,0.5,1
set ytics 0,0.5,1
set xlabel 'x_1'
set ylabel 'x_2'
do for [k=1:3] {
  set arrow from k*0.25, 0 to k*0.25, 1 nohead lc rgb '#888888' lw 1.2 back
  set arrow from 0, k*0.25 to 1, k*0.25 nohead lc rgb '#888888' lw 1.2 back
}
set object 1 rect from 0,0 to 1,1 fs empty border lc rgb 'black' lw 3 back
unset key
set parametric
set trange [0:2*pi]
set datafile separator ','
plot 0.5 + 0.25*cos(t), 0.5 + 0.25*sin(t) with filledcurves lc rgb '#cfe0f5' title 'φ = R on the disk', \
     0.5 + 0.25*cos(t), 0.5 + 0.25*sin(t) with lines lw 2 lc rgb '#1f4e8c' title 'contact circle (10)', \
     'results/fig1_points.csv' using 1:2 with points pt 2 ps 2 lw 2 lc rgb '#c0392b' title 'check points'
unset parametric
unset arrow
unset object 1
unset key
set datafile separator whitespace

set title '(b) w on h = 1/32, contact in red'
set origin 0.3, 0
set size ratio -1 0.37, 1
set xrange [0:1]
set yrange [0:1]
set xtics 0,0.5,1
set ytics 0,0.5,1
set cblabel 'w' offset -0.5,0
set cbtics 0,0.05,0.1
set view map
set pm3d map
set palette rgbformulae 33,13,10
set colorbox
set cbrange [0:0.1]
set contour base
set cntrparam levels incremental 0, 0.01, 0.1
unset clabel
splot 'results/fig1_surface.dat' using 1:2:3 with pm3d nocontour notitle, \
      'results/fig1_surface.dat' using 1:2:3 with lines nosurface lc rgb 'black' lw 0.5 notitle, \
      'results/fig1_contact.dat' using 1:2:3 with points pt 7 ps 0.7 lc rgb '#c0392b' nocontour notitle
unset contour
unset colorbox

set title '(c) section x_2 = 1/2'
set origin 0.69, 0
set size noratio 0.31, 1
set ylabel 'w, φ' offset 1.5,0
set xrange [0:1]
# Headroom above the peak for the key, which then covers no part of the curve.
set yrange [-0.005:0.15]
set xtics 0,0.5,1
set ytics 0,0.05,0.1
set xlabel 'x_1'
set key inside top center vertical samplen 1.5
plot 'results/fig1_surface.dat' index 0 every ::0 using 1:(abs($2 - 0.5) < 1e-9 ? $3 : NaN) with lines lw 2 lc rgb '#1f4e8c' title 'plate w', \
     (x >= 0.25 && x <= 0.75 ? 0.0625 : NaN) with filledcurves y1=0 lc rgb '#cfe0f5' title 'obstacle φ'
unset multiplot
