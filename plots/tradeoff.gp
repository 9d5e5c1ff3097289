# tradeoff.gp - speed against accuracy (the tradeoff experiment): per
# dimension (columns 2D, 3D) and case (rows EE, ES, SQ) the median
# hausdorff_rel of the returned points against the median seconds per
# call, over the pairs of each level, on log-log axes; one curve per
# method found in the data (points joined in order of rising n), and the
# Pareto front over all methods (no point both faster and more accurate)
# as a thick grey staircase with open circles. Each method has its own
# colour and marker (plots/methods.gp); a panel's key lists only the
# methods with points in it. The medians and the front
# come from plots/tradeoff.awk; levels with a non-finite error are left out.
# Writes <outdir>/tradeoff.pdf and tradeoff.png (`formats` changes that).
#
#   gnuplot plots/tradeoff.gp                       (results/tradeoff.csv.gz -> plots/)
#   gnuplot -e "results='results/quick/tradeoff.csv.gz'; outdir='plots/quick'" plots/tradeoff.gp
#
# Run from the top of the project. Reads only the CSV.

if (!exists("results")) results = 'results/tradeoff.csv.gz'
load 'plots/gz.gp'
if (!exists("outdir")) outdir = 'plots'
if (!exists("formats")) formats = 'pdf png'

awk(mode) = sprintf("%s | awk -F, -v mode=%s -f plots/tradeoff.awk", gzcat(results), mode)
names = system(awk("names"))
nmeth = words(names)
set print $P
print system(awk("points"))
unset print
set print $F
print system(awk("front"))
unset print

case_name(c) = word("EE ES SQ", c)
load 'plots/methods.gp'
if (nmeth > mk_styles) { print sprintf("tradeoff.gp: %d methods; only the first %d are drawn", nmeth, mk_styles); nmeth = mk_styles }
color_of(m) = mk_color(m)
pt_of(m) = mk_pt(m)
# `present` holds "|dim case method|" for every (dim, case, method) with a
# point, so that a panel's key lists only the methods drawn in it.
present = "|"
do for [i = 1:|$P|] {
	if (words($P[i]) >= 6) {
		entry = sprintf("%s %s %s", word($P[i], 1), word($P[i], 2), word($P[i], 3))
		if (strstrt(present, "|" . entry . "|") == 0) { present = present . entry . "|" }
	}
}
shown(d, c, m) = strstrt(present, sprintf("|%d %s %s|", d, case_name(c), word(names, m))) > 0
case_title(c) = c == 1 ? "EE: two ellipses / ellipsoids" : c == 2 ? \
	"ES: superellipse / superquadric and ellipse / ellipsoid" : "SQ: two superellipses / superquadrics"
sel(d, c) = (column(1) == d && strcol(2) eq case_name(c))

set datafile separator whitespace
set logscale xy
set grid xtics ytics lc rgb '#dddddd'
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "median time per call (s)"
set ylabel "median Hausdorff error / scale"
set key outside right top font ",7" spacing 0.9 noenhanced

do for [fmt in formats] {
	if (fmt eq "pdf") {
		set terminal pdfcairo size 13in, 13in font "Helvetica,10"
	} else {
		if (fmt eq "svg") {
			set terminal svg size 1700, 1700 font "Helvetica,11"
		} else {
			set terminal pngcairo size 1700, 1700 font "Helvetica,11"
		}
	}
	set output sprintf("%s/tradeoff.%s", outdir, fmt)
	set multiplot layout 3, 2 title "Error against time per call: medians over the pairs of each level (grey: Pareto front)"
	do for [c = 1:3] {
		do for [d = 2:3] {
			set title sprintf("%dD %s", d, case_title(c))
			plot $F using (sel(d, c) ? $3 : NaN):4 with steps lw 6 lc rgb '#bbbbbb' title "Pareto front", \
				$F using (sel(d, c) ? $3 : NaN):4 with points pt 6 ps 1.6 lc rgb '#888888' notitle, \
				for [m = 1:nmeth] $P using (sel(d, c) && strcol(3) eq word(names, m) ? $5 : NaN):6 \
					with linespoints lw 1.5 pt pt_of(m) ps 0.7 lc rgb color_of(m) title (shown(d, c, m) ? word(names, m) : "")
		}
	}
	unset multiplot
	unset output
}
