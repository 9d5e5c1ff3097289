# timing.gp - running time per call of every method (paper Sec. 6.3,
# Figs. 5-8), from the timing driver's raw rows.
#
# One panel per case (rows: EE, ES, SQ) and dimension (columns: 2D, 3D):
# the mean time per call over the trials of each level, with a band of
# +- one population standard deviation (as the paper's shaded regions),
# on log-log axes (times span six decades). Levels whose cell ran fewer
# trials than planned (the driver's time budget; column trials_run) are
# marked with open circles. One curve per method found in the data (see
# below), keyed by its name. Writes <outdir>/timing.pdf and timing.png
# (`formats`, a space-separated choice of pdf, png and svg, changes that).
#
#   gnuplot plots/timing.gp                          (results/timing.csv.gz -> plots/)
#   gnuplot -e "results='results/quick/timing.csv.gz'; outdir='plots/quick'" plots/timing.gp
#
# Run from the top of the project. Reads only the CSV.

if (!exists("results")) results = 'results/timing.csv.gz'
load 'plots/gz.gp'
data = gzdata(results)
if (!exists("outdir")) outdir = 'plots'
if (!exists("formats")) formats = 'pdf png'

set datafile separator comma
set datafile columnheaders

# The methods are those of the data: no list of names lives here. `stats`
# walks the rows once and collects every distinct `method` value, in order
# of first appearance (the driver writes the registry's methods in registry
# order), into the string `found` ("|name|name|...|"); the names then go to
# the array mnames[1..nmeth] and to `ids` ("|name=11|name=12..."), from
# which midx(s) reads a name's index + 10 in two fixed-width digits (up to 89
# methods; never a leading 0, which real() would read as octal). A name must not contain "|" or "=". Key titles are the names
# themselves, printed as they are (noenhanced); each method has its own
# colour and marker (plots/methods.gp), and a panel's key lists only the
# methods with data in it.
load 'plots/methods.gp'
found = "|"
add_method(s) = strstrt(found, "|" . s . "|") > 0 ? 0 : (found = found . s . "|", 1)
stats data using (add_method(strcol("method"))) nooutput
nmeth = 0
rest = found[2:]
do for [i = 1:strlen(found)] {
	if (strlen(rest) > 0) { nmeth = nmeth + 1; rest = rest[strstrt(rest, "|") + 1:] }
}
if (nmeth > mk_styles) { print sprintf("timing.gp: %d methods; only the first %d are drawn", nmeth, mk_styles); nmeth = mk_styles }
array mnames[nmeth > 0 ? nmeth : 1]
ids = ""
rest = found[2:]
do for [i = 1:nmeth] {
	mnames[i] = rest[1:strstrt(rest, "|") - 1]
	rest = rest[strstrt(rest, "|") + 1:]
	ids = ids . sprintf("|%s=%d", mnames[i], i + 10)
}
mpos(s) = strstrt(ids . "|", "|" . s . "=")
midx(s) = mpos(s) > 0 ? int(real(ids[mpos(s) + strlen(s) + 2:mpos(s) + strlen(s) + 3])) - 10 : 0
color_of(m) = mk_color(m)
pt_of(m) = mk_pt(m)
case_title(c) = c == 1 ? "EE: two ellipses / ellipsoids" : c == 2 ? \
	"ES: superellipse / superquadric and ellipse / ellipsoid" : "SQ: two superellipses / superquadrics"

cidx(s) = s eq "EE" ? 1 : s eq "ES" ? 2 : s eq "SQ" ? 3 : 0

# Every (dim, case, method, level) is one integer key; rows that are not
# timed calls of a known method (failed calls included) all go to key -1, so
# that the data stay one block and `smooth unique` averages each key over
# the whole file.
key(d, c, m, p) = (c > 0 && m > 0 && (d == 2 || d == 3)) ? ((d * 4 + c) * 100 + m) * 1e8 + p : -1
rowkey = 'key(column("dim"), cidx(strcol("case")), midx(strcol("method")), column("points_per_body")) * (strcol("status") eq "ok" ? 1 : 0) + (strcol("status") eq "ok" ? 0 : -1)'

# `set table` writes numbers in the axes' formats: keep every digit of the
# keys and the times. The times in %e form: gnuplot's real() refuses an
# integer mantissa with an exponent ("1e-05"), which %g writes for round
# values.
set format x "%.15g"
set format y "%.15e"
set table $M
plot data using (@rowkey):(column("seconds")) smooth unique
set table $S
plot data using (@rowkey):(column("seconds") ** 2) smooth unique
set table $C
plot data using (@rowkey):(column("trials_run") < column("trials_planned") ? 1 : 0) smooth unique
unset table
# $D below is plain whitespace-separated data without a header.
set datafile nocolumnheaders
set datafile separator whitespace

# Join the three tables (same keys, same order) into $D: one block per
# (dim, case, method), columns points, mean, std, capped; blk_<d>_<c>_<m>
# is the block's index. The variance E[t^2] - E[t]^2 is kept at zero or
# above.
set print $D
nblk = 0
prev = -1
do for [i = 1:|$M|] {
	line = $M[i]
	if (strlen(line) > 0 && line[1:1] ne "#" && words(line) >= 2) {
		k = real(word(line, 1))
		if (k >= 0) {
			mean = real(word(line, 2))
			sq = real(word($S[i], 2))
			capped = real(word($C[i], 2)) > 0 ? 1 : 0
			p = k - floor(k / 1e8) * 1e8
			g = floor(k / 1e8)
			if (g != prev) {
				if (prev >= 0) { print ""; print "" }
				eval sprintf("blk_%d_%d_%d = %d", floor(g / 400), int(floor(g / 100)) % 4, int(g) % 100, nblk)
				nblk = nblk + 1
				prev = g
			}
			var = sq - mean * mean
			print sprintf("%.0f %.9g %.9g %d", p, mean, (var > 0 ? sqrt(var) : 0), capped)
		}
	}
}
unset print

has(d, c, m) = exists(sprintf("blk_%d_%d_%d", d, c, m))
blk(d, c, m) = value(sprintf("blk_%d_%d_%d", d, c, m))
# Lower edge of the band: mean - std, or mean / 10 where that is not positive
# (a log axis cannot show it; the key says so).
lo(m, s) = (m - s > 0) ? m - s : m / 10.0

set format x "%g"
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set format y "10^{%T}"
set ylabel "time per call (s)"
set key top left font ",8" spacing 0.9 box opaque
# Room above the curves for the key: the top of each panel is raised by 40%
# of its height (in log units).
set offsets 0, 0, graph 0.4, 0
set style fill transparent solid 0.18 noborder

# Each panel: the bands, then the mean curves, then open circles on capped
# levels.
do for [fmt in formats] {
	if (fmt eq "pdf") {
		set terminal pdfcairo size 11in, 13in font "Helvetica,10"
	} else {
		if (fmt eq "svg") {
			set terminal svg size 1500, 1750 font "Helvetica,11"
		} else {
			set terminal pngcairo size 1500, 1750 font "Helvetica,11"
		}
	}
	set output outdir . '/timing.' . fmt
	set multiplot layout 3, 2 title sprintf("Running time per call, mean ± population std over the trials of each level (from %s)\nopen circles: levels whose cell ran fewer trials than planned (time budget); band lower edge at mean/10 where mean - std <= 0", results)
	do for [c = 1:3] {
		do for [d = 2:3] {
			set title sprintf("%dD, %s", d, case_title(c))
			if (d == 2) {
				set xlabel "points per body N"
			} else {
				set xlabel "points per body n^2 (n x n grid)"
			}
			cmd = ""
			do for [m = 1:nmeth] {
				if (has(d, c, m)) {
					b = blk(d, c, m)
					cmd = cmd . sprintf("%s$D index %d using 1:(lo($2,$3)):($2+$3) with filledcurves lc rgb '%s' notitle", \
						(strlen(cmd) > 0 ? ", " : ""), b, color_of(m))
				}
			}
			do for [m = 1:nmeth] {
				if (has(d, c, m)) {
					b = blk(d, c, m)
					cmd = cmd . sprintf(", $D index %d using 1:2 with linespoints lw 2 pt %d ps 0.6 lc rgb '%s' title mnames[%d] noenhanced", \
						b, pt_of(m), color_of(m), m)
					cmd = cmd . sprintf(", $D index %d using 1:($4 > 0 ? $2 : NaN) with points pt 6 ps 1.4 lc rgb '%s' notitle", \
						b, color_of(m))
				}
			}
			if (strlen(cmd) > 0) {
				eval "plot " . cmd
			} else {
				set label 1 "no rows for this case and dimension in the results" at graph 0.5, 0.5 center
				unset key
				set xrange [10:1000]
				set yrange [1e-6:1]
				plot NaN notitle
				set autoscale xy
				set key
				unset label 1
			}
		}
	}
	unset multiplot
	unset output
}
