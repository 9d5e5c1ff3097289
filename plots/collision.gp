# collision.gp - collision and distance (paper Sec. 7.2, Table 3): the error
# of every registry entry's signed distance against the referee's, against
# its time per query, one panel per pair kind (ellipsoids, superquadrics,
# near-touching, deep overlaps), log-log.
#
# Reads only the collision driver's rows <results> (one per trial and entry).
# Per pair kind and entry that returns a distance (rows with an `error`):
# the point is at the median time and the median error over those rows, the
# bar reaches up to the largest error. Errors are |distance - referee| /
# scale; an exact 0 is drawn at 1e-17. Entries that give a status only
# (no distance: the LM queries, minksum-ray, GJK, MPR, ASC, ...) have no
# error and are not drawn: their times and agreement are in the tables.
# The entries are those of the data (no list of names lives here). The
# paper published times only (Table 3, no errors), so it has no point here.
# Output: <outdir>/collision.pdf and <outdir>/collision.png.
#
#   gnuplot plots/collision.gp                       (results/collision.csv.gz -> plots/)
#   gnuplot -e "results='results/quick/collision.csv.gz'; outdir='plots/quick'" plots/collision.gp
#
# Run from the top of the project.

if (!exists("results")) results = 'results/collision.csv.gz'
load 'plots/gz.gp'
data = gzdata(results)
if (!exists("outdir")) outdir = 'plots'

set datafile separator comma
set datafile columnheaders

# The entries of the data, in order of first appearance, into mnames[1..nmeth]
# (names must not contain "|").
found = "|"
add_method(s) = strstrt(found, "|" . s . "|") > 0 ? 0 : (found = found . s . "|", 1)
stats data using (add_method(strcol("algorithm"))) nooutput
nmeth = 0
rest = found[2:]
do for [i = 1:strlen(found)] {
	if (strlen(rest) > 0) { nmeth = nmeth + 1; rest = rest[strstrt(rest, "|") + 1:] }
}
array mnames[nmeth > 0 ? nmeth : 1]
rest = found[2:]
do for [i = 1:nmeth] {
	mnames[i] = rest[1:strstrt(rest, "|") - 1]
	rest = rest[strstrt(rest, "|") + 1:]
}
# Colours and point types cycle through 16 (the registry has 17 entries).
color_of(m) = word("#1b6ca8 #d1495b #edae49 #00798c #6a994e #8e7dbe #5fa8d3 #3d405b #f4845f #2a9d8f #9c6644 #e07a5f #81b29a #000000 #b5179e #7209b7", (m - 1) % 16 + 1)
pt_of(m) = word("7 5 9 11 13 15 7 5 9 11 13 15 7 5 9 11", (m - 1) % 16 + 1) + 0 + ((m - 1) % 16 >= 6 ? -1 : 0)

array kind[4] = ["ellipsoids", "superquadrics", "near", "deep"]
array ktitle[4] = ["ellipsoids (the paper draw)", "superquadrics (the paper draw)", \
	"near-touching (±1e-1 … ±1e-6 of the size)", "deep overlaps"]

# Which (kind, entry) cells have rows with an error: one pass collects their
# keys "|k:m|" into `cells`, so that stats runs only where there are data.
kidx(s) = s eq "ellipsoids" ? 1 : s eq "superquadrics" ? 2 : s eq "near" ? 3 : s eq "deep" ? 4 : 0
midx(s) = sum [i = 1:nmeth] (mnames[i] eq s ? i : 0)
cells = "|"
add_cell(c) = strstrt(cells, c) > 0 ? 0 : (cells = cells . c[2:], 1)
stats data using (strcol("error") ne "" ? add_cell(sprintf("|%d:%d|", kidx(strcol("pair")), midx(strcol("algorithm")))) : NaN) nooutput

# Per such cell: the median time (µs) and the median and largest error over
# its rows with an error; one line "k m time median max" each into $P.
sel(k, m) = strcol("pair") eq kind[k] && strcol("algorithm") eq mnames[m] && strcol("error") ne ""
floor_err(e) = e > 1e-17 ? e : 1e-17
nrows = 0
set print $P
do for [k = 1:4] {
	do for [m = 1:nmeth] {
		if (strstrt(cells, sprintf("|%d:%d|", k, m)) > 0) {
			stats data using (sel(k, m) ? 1e6 * column("seconds") : NaN) nooutput name "T"
			stats data using (sel(k, m) ? floor_err(column("error")) : NaN) nooutput name "E"
			print sprintf("%d %d %.6g %.6g %.6g", k, m, T_median, E_median, E_max)
			nrows = nrows + 1
		}
	}
}
unset print
stats data using (strcol("pair") eq "ellipsoids" && strcol("algorithm") eq mnames[1] ? 1 : NaN) nooutput
ntrials = exists("STATS_records") ? STATS_records : 0

set print "-"
print sprintf("collision.gp: %s, %d entries, %d trials per pair kind, %d points", results, nmeth, ntrials, nrows)
set print
unset datafile columnheaders
set datafile separator whitespace

# The entries with a point in panel k: list_<k> = "m m ...".
do for [k = 1:4] { eval sprintf("list_%d = ''", k) }
do for [i = 1:|$P|] {
	eval sprintf("list_%s = list_%s . ' %s'", word($P[i], 1), word($P[i], 1), word($P[i], 2))
}
list(k) = value(sprintf("list_%d", k))

# A panel with no point (a run without that pair kind) says so.
panel(k) = sprintf("set title '%s' noenhanced font ',11'; \
if (words(list(%d)) == 0) { set label 1 'no entry returned a distance here' at graph 0.5, 0.5 center; plot NaN notitle; unset label 1 } \
else { plot for [j = 1:words(list(%d))] $P using ($1 == %d && $2 == int(word(list(%d), j)) ? $3 : NaN):4:4:5 \
	with yerrorbars pt pt_of(int(word(list(%d), j))) ps 1.2 lc rgb color_of(int(word(list(%d), j))) \
	title mnames[int(word(list(%d), j))] noenhanced }", ktitle[k], k, k, k, k, k, k, k)

figure = "\
set multiplot layout 2, 2 title sprintf('Collision and distance: error against the referee vs time per query (median; bar to the largest error), %d pairs per kind', ntrials) noenhanced font ',12'; \
set logscale xy; set xrange [0.1:1e6]; set yrange [1e-18:10]; \
set format x '10^{%L}'; set format y '10^{%L}'; \
set xlabel 'time per query (µs, median)'; set ylabel '|distance − referee| / scale'; \
set grid xtics ytics lc rgb '#dddddd'; \
set key bottom right font ',8' box opaque; \
eval panel(1); eval panel(2); eval panel(3); eval panel(4); \
unset multiplot"

set terminal pdfcairo enhanced color size 13in,10in font "Helvetica,10"
set output outdir . '/collision.pdf'
eval figure
set output

set terminal pngcairo enhanced color size 1600,1200 font "Helvetica,11"
set output outdir . '/collision.png'
eval figure
set output
