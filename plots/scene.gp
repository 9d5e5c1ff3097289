# scene.gp - the scene experiment (experiments/scene): C-obstacles certified
# to a tolerance against uniform sampling, and Table 2 on 1 and 2 threads.
#
# Top left and middle: points used (all boundaries of a scene) against the
# tolerance T, 2D and 3D, log-log; filled circles the adaptive mode, open
# squares the smallest uniform sampling with the same worst-case certified
# error (open triangles: the uniform search was capped, so the uniform count
# needed is larger still). Each scene is one pair of points per T; the
# labels give the obstacle count. Top right: Table 2's levels (paper
# sampling) on 1 and 2 threads, measured alternately in one run, wall
# seconds on a log axis, one point per repetition. Bottom row, when the
# driver wrote <result without .csv>/fig9-boundaries.csv (--fig9): one 2D
# scene's C-obstacles at heading 0, the whole scene and two of them
# enlarged (the largest and the smallest), where the band between the
# inner and the outer boundary (the certified tolerance) is seen. Writes
# <outdir>/scene.pdf and scene.png.
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

# Table 2's levels, in order of first appearance: "dim|obstacles|orientations"
# keys into lkeys[1..nlvl] (one x position each).
found = "/"
lkey(unused) = sprintf("%d|%s|%s", int(column("dim")), strcol("obstacles"), strcol("orientations"))
add_level(s) = strstrt(found, "/" . s . "/") > 0 ? 0 : (found = found . s . "/", 1)
stats results using (strcol("part") eq "B" ? add_level(lkey(0)) : NaN) nooutput
nlvl = 0
rest = found[2:]
do for [i = 1:strlen(found)] {
	if (strlen(rest) > 0) { nlvl = nlvl + 1; rest = rest[strstrt(rest, "/") + 1:] }
}
array lkeys[nlvl > 0 ? nlvl : 1]
rest = found[2:]
do for [i = 1:nlvl] {
	lkeys[i] = rest[1:strstrt(rest, "/") - 1]
	rest = rest[strstrt(rest, "/") + 1:]
}
lidx(s) = sum [i = 1:nlvl] (lkeys[i] eq s ? i : 0)
# "2|1000|50" -> "2D\n1000 obst.\n50 rot."
field(s, n) = n == 1 ? s[1:strstrt(s, "|") - 1] : field(s[strstrt(s, "|") + 1:], n - 1)
ltic(s) = sprintf("%sD\n%s obst.\n%s rot.", field(s, 1), field(s, 2), field(s, 3))

# Fig. 9: block 2k of the geometry file is obstacle k's inner boundary,
# block 2k + 1 its outer one (closed outlines). Read by column number: each
# block's first line would otherwise be taken for a header.
if (havefig9) {
	set datafile nocolumnheaders
	stats fig9 using 1 nooutput
	nfig = int(STATS_max) + 1
	array ext[nfig]
	array cx[nfig]
	array cy[nfig]
	do for [k = 0:nfig - 1] {
		stats fig9 index (2 * k + 1) using 3:4 nooutput
		ext[k + 1] = (STATS_max_x - STATS_min_x > STATS_max_y - STATS_min_y) ? STATS_max_x - STATS_min_x : STATS_max_y - STATS_min_y
		cx[k + 1] = (STATS_max_x + STATS_min_x) / 2
		cy[k + 1] = (STATS_max_y + STATS_min_y) / 2
	}
	big = 1; small = 1
	do for [k = 1:nfig] {
		if (ext[k] > ext[big]) { big = k }
		if (ext[k] < ext[small]) { small = k }
	}
	set datafile columnheaders
	call 'plots/sidecar.gp' results 'fig9_tol' 'figtol'
}

# One C-obstacle enlarged: its outer outline filled red, the inner one
# filled white over it, so the band between them is the red ring; the
# vertices of both as points.
zoom(k, tag) = sprintf("set title 'Fig. 9, C-obstacle %s (obstacle %d) enlarged: window %.3g x %.3g'; \
set xrange [%.17g:%.17g]; set yrange [%.17g:%.17g]; \
plot fig9 index %d using 3:4 with filledcurves closed fc rgb '#f4a6a6' title 'between: holds the exact boundary', \
     fig9 index %d using 3:4 with filledcurves closed fc rgb 'white' notitle, \
     fig9 index %d using 3:4 with linespoints lw 2 pt 7 ps 0.9 lc rgb '#d62728' title 'outer boundary', \
     fig9 index %d using 3:4 with linespoints lw 2 pt 7 ps 0.9 lc rgb '#1f77b4' title 'inner boundary'", \
	tag, k - 1, 1.6 * ext[k], 1.6 * ext[k], cx[k] - 0.8 * ext[k], cx[k] + 0.8 * ext[k], cy[k] - 0.65 * ext[k], cy[k] + 0.95 * ext[k], \
	2 * k - 1, 2 * k - 2, 2 * k - 1, 2 * k - 2)

do for [fmt in formats] {
	if (fmt eq "pdf") {
		set terminal pdfcairo size 15in, (havefig9 ? 10.5 : 5)in font "Helvetica,10"
	} else {
		set terminal pngcairo size 1800, (havefig9 ? 1260 : 600) font "Helvetica,11"
	}
	set output outdir . '/scene.' . fmt
	top = havefig9 ? 0.5 : 0.0
	high = havefig9 ? 0.5 : 1.0
	set multiplot title "C-obstacles certified to a tolerance (adaptive vs uniform sampling), Table 2 on 1 and 2 threads" . (havefig9 ? ", and Fig. 9's scene" : "")
	do for [d = 2:3] {
		set origin (d - 2) / 3.0, top
		set size 1 / 3.0, high * 0.96
		set title sprintf("%dD: points used against the tolerance", d)
		unset logscale
		# the tolerances of this dimension, larger on the left, half a decade of margin
		# (a run with one tolerance would leave autoscale an empty range)
		stats results using (isA(d, "adaptive") ? column("tol") : NaN) nooutput
		set logscale xy
		set xlabel "certified tolerance T (scene units; smaller is finer)" offset 0, 0
		set ylabel "points (all boundaries of the scene)"
		set key bottom right nobox noopaque
		set xrange [STATS_max * 3.0 : STATS_min / 3.0]
		plot results using (isA(d, "adaptive") ? column("tol") : NaN):(column("points")) with points pt 7 ps 1.2 lc rgb "#1f77b4" title "adaptive", \
		     results using (isA(d, "uniform") && capped(0) ? column("tol") : NaN):(column("points")) with points pt 4 ps 1.4 lc rgb "#d62728" title "uniform, same worst-case error", \
		     results using (isA(d, "uniform") && capped(1) ? column("tol") : NaN):(column("points")) with points pt 8 ps 1.4 lc rgb "#d62728" title "uniform, capped (needs more)", \
		     results using (isA(d, "adaptive") ? column("tol") : NaN):(column("points")):(strcol("obstacles") . " obst.") with labels offset 2.2, -0.8 font ",8" notitle
		set xrange [*:*] noreverse
	}
	set origin 2 / 3.0, top
	set size 1 / 3.0, high * 0.96
	set title "Table 2 (paper sampling): wall time of each level"
	unset logscale
	set logscale y
	set xlabel "level: dimension, obstacles, orientations of the robot" offset 0, -1.2
	set bmargin 6
	set ylabel "wall time (s)"
	set key top left nobox noopaque
	set xrange [0.5 : nlvl + 0.5]
	set xtics () font ",9"
	do for [i = 1:nlvl] { set xtics add (ltic(lkeys[i]) i) }
	set grid ytics
	plot results using (isB(1) ? lidx(lkey(0)) - 0.12 : NaN):(column("seconds")) with points pt 7 ps 1.3 lc rgb "#1f77b4" title "1 thread", \
	     results using (isB(2) ? lidx(lkey(0)) + 0.12 : NaN):(column("seconds")) with points pt 5 ps 1.3 lc rgb "#2ca02c" title "2 threads"
	unset grid
	set bmargin
	set xtics autofreq font ""
	set xrange [*:*]
	unset logscale
	if (havefig9) {
		set datafile nocolumnheaders
		set origin 0, 0
		set size 1 / 3.0, 0.48
		set title sprintf("Fig. 9: the 2D scene's %d C-obstacles at heading 0 (T = %g)", nfig, figtol)
		set size ratio -1
		set xlabel "x (scene units)" offset 0, 0
		set ylabel "y (scene units)"
		set key off
		do for [k in sprintf("%d %d", big, small)] {
			kk = k + 0
			set object kk rect center cx[kk], cy[kk] size 1.3 * ext[kk], 1.3 * ext[kk] fs empty border rgb "black" dt 2
			tag = kk == big ? "A" : "B"
			set label kk tag at cx[kk] + 0.65 * ext[kk], cy[kk] + 0.65 * ext[kk] offset 0.3, 0.3 font ",10"
		}
		plot fig9 using 3:4 with filledcurves closed fc rgb '#d62728' notitle
		unset object
		unset label
		set key top left box opaque
		set origin 1 / 3.0, 0
		eval zoom(big, "A")
		set origin 2 / 3.0, 0
		eval zoom(small, "B")
		set xrange [*:*]
		set yrange [*:*]
		set size noratio
		set datafile columnheaders
	}
	unset multiplot
	unset output
}
