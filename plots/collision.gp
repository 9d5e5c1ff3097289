# collision.gp - collision detection (paper Sec. 7.2, Table 3): the time per
# query of every algorithm on the two kinds of pairs, measured here beside
# the paper's published means.
#
# Reads only the collision driver's rows <results> (one per trial and
# algorithm; column `seconds` is the query alone). Per pair kind and
# algorithm it draws the mean (filled circle, labelled), the median (open
# circle) and the interquartile range of the measured times, and the
# published mean as a grey bar. The published means are Table 3 of Ruan &
# Chirikjian (2022), MATLAB on a 2.8 GHz Xeon; ASC was run on ellipsoids only.
# Output: <outdir>/collision.pdf and <outdir>/collision.png.
#
#   gnuplot plots/collision.gp                       (results/collision.csv -> plots/)
#   gnuplot -e "results='results/quick/collision.csv'; outdir='plots/quick'" plots/collision.gp
#
# Run from the top of the project.

if (!exists("results")) results = 'results/collision.csv'
if (!exists("outdir")) outdir = 'plots'

set datafile separator comma
set datafile columnheaders

nalg = 6
array alg[nalg] = ["GJK", "ASC", "Implicit", "Common Normal", "MinkSum (Ray)", "MinkSum (Normal)"]
array pair[2] = ["ellipsoids", "superquadrics"]
# Which algorithms are iterative solvers (a success column), and which run on
# superquadrics (ASC is for ellipsoids only).
array solver[nalg] = [0, 0, 1, 1, 1, 1]
array onsq[nalg] = [1, 0, 1, 1, 1, 1]
# Published mean times (ms), paper Table 3; NaN where the paper has none.
array pub1[nalg] = [18.4, 0.133, 27.0, 4.1, 3.5, 3.5]
array pub2[nalg] = [18.3, NaN, 42.3, 7.1, 5.2, 5.1]

# Per pair kind p and algorithm a: queries, mean, median, lower and upper
# quartile of the time in ms, and the success rate of the solvers.
ms(p, a) = (strcol("pair") eq pair[p] && strcol("algorithm") eq alg[a]) ? 1e3 * column("seconds") : NaN
ok(p, a) = (strcol("pair") eq pair[p] && strcol("algorithm") eq alg[a] && strcol("success") ne "") ? column("success") : NaN
array cnt[2 * nalg]; array mean[2 * nalg]; array med[2 * nalg]; array lo[2 * nalg]; array hi[2 * nalg]
array succ[2 * nalg]
do for [p = 1:2] {
	do for [a = 1:nalg] {
		i = (p - 1) * nalg + a
		cnt[i] = 0; mean[i] = NaN; med[i] = NaN; lo[i] = NaN; hi[i] = NaN; succ[i] = NaN
		undefine STATS_*
		# stats leaves STATS_records undefined when no row matches (a quick
		# run of one pair kind only).
		if (p == 1 || onsq[a]) { stats results using (ms(p, a)) nooutput }
		if (exists("STATS_records") && STATS_records > 0) {
			cnt[i] = STATS_records; mean[i] = STATS_mean; med[i] = STATS_median
			lo[i] = STATS_lo_quartile; hi[i] = STATS_up_quartile
			undefine STATS_*
			if (solver[a]) { stats results using (ok(p, a)) nooutput }
			if (exists("STATS_records") && STATS_records > 0) { succ[i] = STATS_mean }
		}
	}
}

stats results using (ms(1, 1)) nooutput
ntrials = STATS_records

set print "-"
print sprintf("collision.gp: %s, %d trials per pair kind", results, ntrials)
set print

panel(p) = sprintf("\
set title '%s' font ',11'; \
set xrange [0.4:%d.6]; \
set xtics () rotate by -25 font ',9'; \
do for [a = 1:nalg] { set xtics add (alg[a] a) }; \
do for [a = 1:nalg] { i = (%d - 1) * nalg + a; if (cnt[i] > 0) { \
	set label 100 + a sprintf('%%.3g ms', mean[i]) at a + 0.12, mean[i] left front font ',8' tc rgb '#d1495b' } }; \
do for [a = 1:nalg] { v = %d == 1 ? pub1[a] : pub2[a]; if (v == v) { \
	set label 300 + a sprintf('%%.3g ms', v) at a, v * 1.6 center front font ',8' tc rgb '#555555' } }; \
if (%d == 2) { set label 400 'ellipsoids only' at 2, 3e-4 center front font ',8' tc rgb '#555555' }; \
do for [a = 1:nalg] { i = (%d - 1) * nalg + a; if (cnt[i] > 0 && succ[i] == succ[i]) { \
	set label 200 + a sprintf('success %%.1f%%%%', 100 * succ[i]) at a, 3e-4 center front font ',7' tc rgb '#555555' } }; \
plot $pubdata using 1:(column(%d + 1)) with boxes lc rgb '#bbbbbb' title 'published mean (MATLAB)', \
     $meas using 1:(column(%d * 5 - 2)):(column(%d * 5)):(column(%d * 5 + 1)) with yerrorbars pt -1 lw 1.2 lc rgb '#d1495b' title 'interquartile range here', \
     $meas using 1:(column(%d * 5 - 2)) with points pt 7 ps 1.2 lc rgb '#d1495b' title 'mean here (one thread)', \
     $meas using 1:(column(%d * 5 - 1)) with points pt 6 ps 1.4 lc rgb '#1b6ca8' title 'median here'; \
unset label", pair[p], nalg, p, p, p, p, p, p, p, p, p, p)

# Datablocks the panels plot: published means per algorithm, and the
# measured figures: column 1 the algorithm, then five columns per pair kind p
# (queries, mean, median, lower and upper quartile) from column 5p - 3 on.
set print $pubdata
do for [a = 1:nalg] { print sprintf("%d %g %g", a, pub1[a], pub2[a]) }
set print
set print $meas
do for [a = 1:nalg] {
	s = sprintf("%d", a)
	do for [p = 1:2] {
		i = (p - 1) * nalg + a
		s = s . sprintf(" %d %g %g %g %g", cnt[i], cnt[i] > 0 ? mean[i] : NaN, cnt[i] > 0 ? med[i] : NaN, \
			cnt[i] > 0 ? lo[i] : NaN, cnt[i] > 0 ? hi[i] : NaN)
	}
	print s
}
set print
unset datafile columnheaders
set datafile separator whitespace

figure = "\
set multiplot layout 1, 2 title sprintf('Collision detection (paper Sec. 7.2, Table 3): time per query, %d random pose pairs of each kind (%s)', ntrials, results) font ',12'; \
set logscale y; set yrange [1e-4:1e3]; set format y '10^{%L}'; \
set ylabel 'time per query (ms)'; \
set grid ytics lc rgb '#dddddd'; \
set key top left font ',9' box opaque; \
set style fill solid 1.0 border lc rgb '#666666'; set boxwidth 0.6; \
eval panel(1); \
unset key; unset ylabel; \
eval panel(2); \
unset multiplot"

set terminal pdfcairo enhanced color size 13in,6in font "Helvetica,10"
set output outdir . '/collision.pdf'
eval figure
set output

set terminal pngcairo enhanced color size 1600,740 font "Helvetica,11"
set output outdir . '/collision.png'
eval figure
set output
