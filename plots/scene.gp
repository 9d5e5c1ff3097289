# scene.gp - the scene experiment (experiments/scene): C-obstacles certified
# to a tolerance against uniform sampling, and Table 2 on 1 and 2 threads.
#
# Left and middle: points used (all boundaries of a scene) against the
# tolerance T, 2D and 3D, log-log; filled circles the adaptive mode, open
# squares the smallest uniform sampling with the same worst-case certified
# error (open triangles: the uniform search was capped, so the uniform count
# needed is larger still). Each scene is one pair of points per T; the
# labels give the obstacle count. Right: Table 2's levels (paper sampling)
# on 1 and 2 threads, measured alternately in one run, wall seconds on a log
# axis. Fourth panel, when the driver wrote <result without .csv>/fig9-
# boundaries.csv (--fig9): one 2D scene's C-obstacles at heading 0, the
# inner and outer boundaries. Writes <outdir>/scene.pdf and scene.png.
#
#   gnuplot -e "results='results/scene.csv'; outdir='plots'" plots/scene.gp
#
# Run from the top of the project. Reads only the CSV.

if (!exists("results")) results = 'results/scene.csv'
if (!exists("outdir")) outdir = 'plots'
if (!exists("formats")) formats = 'pdf png'

set datafile separator comma
set datafile columnheaders

# Fig. 9's geometry, when the driver wrote it (--fig9): beside the result.
geom = (strlen(results) > 4 && results[strlen(results)-3:] eq '.csv') ? results[1:strlen(results)-4] : results
fig9 = geom . '/fig9-boundaries.csv'
havefig9 = system("test -r '" . fig9 . "' && echo 1 || echo 0") + 0
isA(d, m) = (strcol("part") eq "A" && int(column("dim")) == d && strcol("mode") eq m)
capped(c) = (int(column("capped")) == c)
isB(t) = (strcol("part") eq "B" && int(column("threads")) == t)

do for [fmt in formats] {
	if (fmt eq "pdf") {
		set terminal pdfcairo size (havefig9 ? 20 : 15)in, 5in font "Helvetica,10"
	} else {
		set terminal pngcairo size (havefig9 ? 2400 : 1800), 600 font "Helvetica,11"
	}
	set output outdir . '/scene.' . fmt
	set multiplot layout 1, (havefig9 ? 4 : 3) title "C-obstacles certified to a tolerance (adaptive vs uniform) and Table 2 on 1 and 2 threads"
	do for [d = 2:3] {
		set title sprintf("%dD: points used against the tolerance", d)
		unset logscale
		# the tolerances of this dimension, larger on the left, half a decade of margin
		# (a run with one tolerance would leave autoscale an empty range)
		stats results using (isA(d, "adaptive") ? column("tol") : NaN) nooutput
		set logscale xy
		set xlabel "tolerance T"
		set ylabel "points (all boundaries of the scene)"
		set key top right
		set xrange [STATS_max * 3.0 : STATS_min / 3.0]
		plot results using (isA(d, "adaptive") ? column("tol") : NaN):(column("points")) with points pt 7 ps 1.2 lc rgb "#1f77b4" title "adaptive", \
		     results using (isA(d, "uniform") && capped(0) ? column("tol") : NaN):(column("points")) with points pt 4 ps 1.4 lc rgb "#d62728" title "uniform, same worst-case error", \
		     results using (isA(d, "uniform") && capped(1) ? column("tol") : NaN):(column("points")) with points pt 8 ps 1.4 lc rgb "#d62728" title "uniform, capped (needs more)", \
		     results using (isA(d, "adaptive") ? column("tol") : NaN):(column("points")):(strcol("obstacles")) with labels offset 1.5, -0.8 font ",8" notitle
		set xrange [*:*] noreverse
	}
	set title "Table 2 (paper sampling), wall time"
	unset logscale x
	set logscale y
	set xlabel "row of the result (labels: dim / obstacles / orientations)"
	set ylabel "seconds"
	set key top left
	set offsets 0.5, 0.5, 0, 0
	plot results using (isB(1) ? $0 : NaN):(column("seconds")) with points pt 7 ps 1.2 lc rgb "#1f77b4" title "1 thread", \
	     results using (isB(2) ? $0 - 1 : NaN):(column("seconds")) with points pt 5 ps 1.2 lc rgb "#2ca02c" title "2 threads", \
	     results using (isB(1) ? $0 : NaN):(column("seconds")):(sprintf("%dD/%s/%s", int(column("dim")), strcol("obstacles"), strcol("orientations"))) with labels offset 0, 1.2 font ",8" notitle
	if (havefig9) {
		set offsets 0, 0, 0, 0
		set title "Fig. 9: C-obstacles at heading 0, inner (blue) and outer (red) boundaries"
		unset logscale
		set size ratio -1
		set xlabel "x"
		set ylabel "y"
		set key top left
		plot fig9 using (strcol("bound") eq "outer" ? column("x") : NaN):(column("y")) with lines lw 1.5 lc rgb "#d62728" title "outer", \
		     fig9 using (strcol("bound") eq "inner" ? column("x") : NaN):(column("y")) with lines lw 1 lc rgb "#1f77b4" title "inner"
		set size noratio
	}
	unset multiplot
	unset output
}
