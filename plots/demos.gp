# demos.gp - the paper's demonstration figures 1-4 from the demos driver's
# geometry.
#
# Reads only results: the index <results> (default results/demos.csv) and
# the geometry files in the directory named like it without ".csv". Writes
#   <outdir>/demos-fig1.png   Fig. 1, definition vs closed form
#   <outdir>/demos-fig2.png   Fig. 2, the two theorems
#   <outdir>/demos-fig3.png   Fig. 3, 2D pairs: canonical, rotated, sheared, both
#   <outdir>/demos-fig4.png   Fig. 4, 3D superquadrics and primitives
#   <outdir>/demos.pdf        the four figures, one per page
#   <outdir>/demos.png        an overview: one panel of each figure
#
#   gnuplot plots/demos.gp                          (results/demos.csv -> plots/)
#   gnuplot -e "results='results/quick/demos.csv'; outdir='plots/quick'" plots/demos.gp
#
# Run from the top of the project. Every 2D panel has equal axis scales and
# every 3D panel equal x, y, z scales. The bodies' parameters are in the
# index (SPEC text) and in each file's .meta sidecar.

if (!exists("results")) results = 'results/demos.csv'
if (!exists("outdir")) outdir = 'plots'
dir = (strlen(results) > 4 && results[strlen(results)-3:] eq '.csv') ? results[1:strlen(results)-4] : results
f1b = dir . '/fig1-bodies.csv'
f1p = dir . '/fig1-pairwise.csv'
f1c = dir . '/fig1-closed.csv'
f2c = dir . '/fig2-curves.csv'
f2b = dir . '/fig2-bodies.csv'
f2k = dir . '/fig2-contact.csv'
f3 = dir . '/fig3.csv'
f4(p) = dir . '/fig4-' . p . '.csv'

set datafile separator comma
set datafile columnheaders

c_b1 = '#2e9d4a'      # B1: green (Figs. 1, 2, 4) and grey in Fig. 3, as in the paper
c_b2 = '#2a6fdb'      # B2: blue
c_sum = '#d62728'     # the Minkowski-sum boundary: red (2D)
c_sum3 = '#80f2c12e'  # ... and transparent yellow (3D; alpha in the top byte)
c_def = '#555555'     # the definition's point cloud

is(col, v) = strcol(col) eq v

# Fig. 2: the contact's vectors are drawn at a common scale (the longest is
# 1.6 units long) so that their lengths compare.
stats f2k using (column("v1_norm") > column("v2_norm") ? column("v1_norm") : column("v2_norm")) nooutput
vscale = 1.6 / STATS_max
stats f2k using (column("x_difference")) nooutput
xdiff = STATS_max

# ---- Fig. 1 ------------------------------------------------------------------
t1a3 = '(a) definition: all 2500 x_{1,i} - x_{2,j}'
fig1a1 = "\
set title '(a) B_1: its 50 samples x_1({/Symbol q}_k)'; \
plot f1b using (is('body', 'b1') ? column('x') : NaN):'y' with lines lw 1.5 lc rgb c_b1 title 'B_1', \
     f1b using (is('body', 'b1') && column('k') < 50 ? column('x') : NaN):'y' with points pt 3 ps 0.7 lc rgb 'black' title 'samples'"
fig1a2 = "\
set title '(a) -B_2: its 50 samples -x_2({/Symbol q}_k)'; \
plot f1b using (is('body', 'minus_b2') ? column('x') : NaN):'y' with lines lw 1.5 lc rgb c_b2 title '-B_2', \
     f1b using (is('body', 'minus_b2') && column('k') < 50 ? column('x') : NaN):'y' with points pt 3 ps 0.7 lc rgb 'black' title 'samples'"
fig1a3 = "\
set title t1a3; \
plot f1p using 'x':'y' with points pt 7 ps 0.25 lc rgb c_def title 'x_{1,i} - x_{2,j}', \
     f1c using 'x':'y' with lines dt 2 lw 1.5 lc rgb c_sum title 'closed form (for comparison)'"
fig1b = "\
set title '(b) closed form: x_{1+2̄}({/Symbol q}_k) from x_1({/Symbol q}_k), same {/Symbol q}_k'; \
plot f1c using 'x1':'y1':(column('x') - column('x1')):(column('y') - column('y1')) with vectors nohead lw 0.5 lc rgb '#bbbbbb' title 'same parameter {/Symbol q}_k', \
     f1c using 'x1':'y1' with linespoints pt 3 ps 0.7 lw 1.2 lc rgb c_b1 title 'B_1, x_1({/Symbol q}_k)', \
     f1c using 'x':'y' with linespoints pt 7 ps 0.6 lw 1.5 lc rgb c_sum title '{/Symbol \266}[B_1 {/Symbol \305} (-B_2)], 50 points'"
fig1 = "\
set multiplot layout 1,4 title 'Fig. 1: the Minkowski sum B_1 {/Symbol \305} (-B_2) by its definition and in closed form (SE(a=(10,8.6), {/Symbol e}=0.36), SE(a=(9.4,6.8), {/Symbol e}=1.28), N = 50)' font ',13'; \
set size ratio -1; set key bottom center outside font ',9'; set grid lc rgb '#eeeeee'; \
set xrange [-30:30]; set yrange [-25:25]; set xtics 10; set ytics 10; set xlabel 'x'; set ylabel 'y'; \
eval fig1a1; eval fig1a2; eval fig1a3; eval fig1b; \
unset multiplot"

# ---- Fig. 2 ------------------------------------------------------------------
# The section drawn in red: the parameters within 20 steps (of 100) of the
# contact's, in each theorem's own parameterisation.
wrap(a) = a - 2 * pi * floor((a + pi) / (2 * pi))
sec(th, a) = abs(wrap(a - (th == 1 ? pa1 : pa2))) <= 20 * 2 * pi / 100 + 1e-9
p2 = ''   # a prefix of the panel titles (the overview names the figure)
fig2panel(th) = sprintf("\
set title '%s%s'; \
plot f2b using (column('theorem') == %d && is('body', 'b1') ? column('x') : NaN):'y' with filledcurves closed fs transparent solid 0.30 lc rgb c_b1 title 'B_1', \
     f2b using (column('theorem') == %d && is('body', 'b2') ? column('x') : NaN):'y' with filledcurves closed fs transparent solid 0.30 lc rgb c_b2 title 'B_2 placed at x_{1+2̄}', \
     f2c using (column('theorem') == %d ? column('x') : NaN):'y' with lines dt 3 lw 1 lc rgb '#999999' title 'whole boundary', \
     f2c using (column('theorem') == %d && sec(%d, column('param_angle')) ? column('x') : NaN):'y' with lines lw 3 lc rgb c_sum title 'a section of {/Symbol \266}[B_1 {/Symbol \305} (-B_2)]', \
     f2k using (column('theorem') == %d ? column('c1x') : NaN):'c1y':(column('px') - column('c1x')):(column('py') - column('c1y')) with vectors nohead dt 2 lc rgb 'black' notitle, \
     f2k using (column('theorem') == %d ? column('c2x') : NaN):'c2y':(column('px') - column('c2x')):(column('py') - column('c2y')) with vectors nohead dt 2 lc rgb 'black' notitle, \
     f2k using (column('theorem') == %d ? column('c1x') : NaN):'c1y':(column('c2x') - column('c1x')):(column('c2y') - column('c1y')) with vectors nohead dt 2 lc rgb 'black' notitle, \
     f2k using (column('theorem') == %d ? column('px') : NaN):'py':(vscale * column('v1x')):(vscale * column('v1y')) with vectors head filled size 0.25,20 lw 2.5 lc rgb c_b1 title '%s', \
     f2k using (column('theorem') == %d ? column('px') : NaN):'py':(vscale * column('v2x')):(vscale * column('v2y')) with vectors head filled size 0.25,20 lw 2.5 lc rgb c_b2 title '%s', \
     f2k using (column('theorem') == %d ? column('c1x') : NaN):'c1y':('c_1') with labels point pt 3 ps 1.5 offset -1.5,-0.5 notitle, \
     f2k using (column('theorem') == %d ? column('c2x') : NaN):'c2y':('c_2 = x_{1+2̄}') with labels point pt 3 ps 1.5 offset 0,-1 left notitle, \
     f2k using (column('theorem') == %d ? column('px') : NaN):'py' with points pt 7 ps 1.2 lc rgb 'black' title 'contact point'", \
	p2, th == 1 ? "(a) Theorem 1: both bodies parameterised by the unit normal, f̃_1(n_1) and f̃_2(-n_1)" \
	        : "(b) Theorem 2: parameterised by gradients m_1 and m_2 = -{/Symbol F}(m_1)/|m_1| m_1", \
	th, th, th, th, th, th, th, th, th, \
	th == 1 ? "n_1 (unit normal of B_1)" : sprintf("m_1, gradient of B_1 (|m_1| = %.3f)", m1n), \
	th, \
	th == 1 ? "-n_1 (unit normal of B_2)" : sprintf("m_2, gradient of B_2 (|m_2| = %.3f)", m2n), \
	th, th, th, th)
stats f2k using (column("theorem") == 1 ? column("param_angle") : NaN) nooutput
pa1 = STATS_max
stats f2k using (column("theorem") == 2 ? column("param_angle") : NaN) nooutput
pa2 = STATS_max
stats f2k using (column("theorem") == 2 ? column("v1_norm") : NaN) nooutput
m1n = STATS_max
stats f2k using (column("theorem") == 2 ? column("v2_norm") : NaN) nooutput
m2n = STATS_max
fig2 = "\
set multiplot layout 1,2 title sprintf('Fig. 2: the two theorems (SE((3.3,2.6), 0.73) and SE((2.4,2), 1.28), N = 100); the two sum points differ by %.1e', xdiff) font ',13'; \
set size ratio -1; set key bottom center outside font ',9' maxrows 5; unset grid; \
unset xrange; unset yrange; set autoscale; set xtics autofreq; set ytics autofreq; set xlabel 'x'; set ylabel 'y'; \
eval fig2panel(1); eval fig2panel(2); \
unset multiplot"

# ---- Fig. 3 ------------------------------------------------------------------
fig3panel(p, t) = sprintf("\
set title '%s'; \
plot f3 using (is('panel', '%s') && is('curve', 'b1') ? column('x') : NaN):'y' with filledcurves closed fs solid 0.35 lc rgb '#777777' title 'B_1', \
     f3 using (is('panel', '%s') && is('curve', 'b2') ? column('x') : NaN):'y' with lines lw 1.2 lc rgb c_b2 title 'B_2 at 10 places', \
     f3 using (is('panel', '%s') && is('curve', 'sum') ? column('x') : NaN):'y' with lines lw 2 lc rgb c_sum title '{/Symbol \266}[B_1 {/Symbol \305} (-B_2)], closed form', \
     f3 using (is('panel', '%s') && is('curve', 'sum') && int(column('k')) %% 10 == 0 && column('k') < 100 ? column('x') : NaN):'y' with points pt 7 ps 0.8 lc rgb 'black' title 'B_2 centres'", \
	t, p, p, p, p)
fig3 = "\
set multiplot layout 2,2 title 'Fig. 3: B_1 = SE((5.2,3.1), 0.45) and B_2 = SE((2.6,1.5), 1.55): canonical, rotated (π/5, -2π/7), sheared (0.8, -0.6), both; N = 100' font ',13'; \
set size ratio -1; set key bottom center outside horizontal font ',9'; set grid lc rgb '#eeeeee'; \
set xrange [-13:13]; set yrange [-11:11]; set xtics 5; set ytics 5; set xlabel 'x'; set ylabel 'y'; \
eval fig3panel('canonical', '(a) canonical forms'); \
eval fig3panel('rotated', '(b) pure rotations'); \
eval fig3panel('sheared', '(c) pure shears'); \
eval fig3panel('rotated+sheared', '(d) rotation and shear'); \
unset multiplot"

# ---- Fig. 4 ------------------------------------------------------------------
# Surfaces by data block: 0 = B1, 1 = the sum, 2 = B2 placed on it; columns
# 4:5:6 are x, y, z (names are read from the first block only).
fig4panel(p, t) = sprintf("\
set title '%s' offset 0,-1; \
splot f4('%s') index 0 using 4:5:6 with pm3d fc rgb c_b1 title 'B_1', \
      f4('%s') index 1 using 4:5:6 with pm3d fc rgb c_sum3 title 'B_1 {/Symbol \305} (-B_2)', \
      f4('%s') index 2 using 4:5:6 with pm3d fc rgb c_b2 title 'B_2'", t, p, p, p)
setup3d = "\
set view 60, 30, 1.25, 1.0; set view equal xyz; set size noratio; \
set pm3d depthorder lighting primary 0.55 specular 0.0; set pm3d noborder; unset colorbox; \
unset grid; set xtics autofreq; set ytics autofreq; set ztics autofreq; unset xlabel; unset ylabel; unset zlabel; \
set xtics font ',7' offset 0,-0.3; set ytics font ',7' offset 0,-0.3; set ztics font ',7'; \
set border 4095 lc rgb '#cccccc'; set xyplane 0; unset key"
fig4 = "\
set multiplot layout 2,4 title 'Fig. 4: 3D superquadrics and primitives on 50 x 50 grids: B_1 (green), B_2 (blue) placed on the closed-form boundary of B_1 {/Symbol \305} (-B_2) (yellow)' font ',13'; \
eval setup3d; \
eval fig4panel('a', '(a) two superquadrics, canonical'); \
eval fig4panel('b', '(b) two superquadrics, rotated'); \
eval fig4panel('c', '(c) two cubes'); \
eval fig4panel('d', '(d) cube and elliptic cylinder'); \
eval fig4panel('e', '(e) two parallelepipeds'); \
eval fig4panel('f', '(f) parallelepiped and elliptic cylinder'); \
eval fig4panel('g', '(g) two elliptic cylinders'); \
eval fig4panel('h', '(h) two ellipsoids'); \
unset multiplot; set border 31 lc rgb 'black'; unset view"

# ---- overview: one panel of each figure --------------------------------------
overview = "\
set multiplot layout 2,2 title 'The demonstration figures of the paper (details in demos-fig1..4.png)' font ',13'; \
set size ratio -1; set key bottom center outside font ',8'; set grid lc rgb '#eeeeee'; \
unset xrange; unset yrange; set autoscale; set xtics autofreq; set ytics autofreq; set xlabel 'x'; set ylabel 'y'; \
t1a3 = 'Fig. 1(a): the definition, all 2500 x_{1,i} - x_{2,j}'; eval fig1a3; \
set key maxrows 4; unset grid; p2 = 'Fig. 2'; eval fig2panel(2); p2 = ''; \
set grid lc rgb '#eeeeee'; eval fig3panel('rotated+sheared', 'Fig. 3(d): rotation and shear'); \
eval setup3d; eval fig4panel('e', 'Fig. 4(e): two parallelepipeds'); \
unset multiplot; set border 31 lc rgb 'black'; t1a3 = '(a) definition: all 2500 x_{1,i} - x_{2,j}'"

# ---- output ------------------------------------------------------------------
# `reset` between figures clears the previous figure's settings (3D view,
# pm3d, ranges) but keeps the variables; the data-file settings come back
# with `init`.
init = "reset; set datafile separator comma; set datafile columnheaders"

set terminal pdfcairo enhanced color size 14in,8.5in font "Helvetica,10"
set output outdir . '/demos.pdf'
eval init; eval fig1
eval init; eval fig2
eval init; eval fig3
eval init; eval fig4
set output

set terminal pngcairo enhanced color size 2000,640 font "Helvetica,11"
set output outdir . '/demos-fig1.png'
eval init; eval fig1
set output

set terminal pngcairo enhanced color size 1700,900 font "Helvetica,11"
set output outdir . '/demos-fig2.png'
eval init; eval fig2
set output

set terminal pngcairo enhanced color size 1500,1250 font "Helvetica,11"
set output outdir . '/demos-fig3.png'
eval init; eval fig3
set output

set terminal pngcairo enhanced color size 2000,1100 font "Helvetica,11"
set output outdir . '/demos-fig4.png'
eval init; eval fig4
set output

set terminal pngcairo enhanced color size 1600,1400 font "Helvetica,11"
set output outdir . '/demos.png'
eval init; eval overview
set output
