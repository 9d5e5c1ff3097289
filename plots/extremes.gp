# extremes.gp - the stability map of the extremes experiment: for every
# method in the data, one panel per dimension over the exponent grid (the
# "eps" family of cells), colour = log10 of error_rel (the largest distance
# of an output point from the exact boundary, over the scale).
#  2D: x = body 1's eps, y = body 2's eps.
#  3D: x = eps1, y = eps2 (both bodies take the cell's pair).
# The axes run log10(eps) up to eps = 1 and -log10(2 - eps) beyond, so that
# both ends of the range (1e-6 and 2 - 1e-6) are six decades from 1. The set
# drawn is `heatset` (default contact; -e "heatset='plus'" for the other).
# Rows whose method returned an error, or that have non-finite points, are
# marked with a black cross over their cell; a cell with no row is empty.
# Writes <outdir>/extremes.pdf and extremes.png (`formats` changes that).
#
#   gnuplot -e "results='results/extremes.csv.gz'; outdir='plots'" plots/extremes.gp
#
# Run from the top of the project. Reads only the CSV.

if (!exists("results")) results = 'results/extremes.csv.gz'
load 'plots/gz.gp'
data = gzdata(results)
if (!exists("outdir")) outdir = 'plots'
if (!exists("formats")) formats = 'pdf png'
if (!exists("heatset")) heatset = 'contact'

set datafile separator comma
set datafile columnheaders

# The methods of the data, in order of first appearance (the driver writes
# them in registry order): no list of names lives here.
found = "|"
add_method(s) = strstrt(found, "|" . s . "|") > 0 ? 0 : (found = found . s . "|", 1)
stats data using (add_method(strcol("method"))) nooutput
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

pos(e) = e <= 1 ? log10(e) : -log10(2 - e)
pick(d, m) = column("dim") == d && strcol("method") eq m && strcol("family") eq "eps" && strcol("set") eq heatset
xof(d) = pos(column("eps1_b1"))
yof(d) = pos(d == 2 ? column("eps1_b2") : column("eps2_b1"))
# log10 of the error, floored at 1e-18 (an exact zero) and blank when missing.
lerr(v) = v > 0 ? log10(v) : (v == 0 ? -18 : NaN)
bad(d, m) = pick(d, m) && (strcol("status") ne "ok")

set xrange [-6.6:6.6]
set yrange [-6.6:6.6]
set xtics ("1e-6" -6, "1e-3" -3, "1" 0, "2-1e-3" 3, "2-1e-6" 6) font ",8" rotate by 35 right
set ytics ("1e-6" -6, "1e-3" -3, "1" 0, "2-1e-3" 3, "2-1e-6" 6) font ",8"
set cbrange [-17:0]
set cblabel "log10 error_rel" noenhanced
set palette defined (-17 "#1a2a6c", -13 "#2a9d8f", -12 "#e9c46a", -6 "#f4a261", 0 "#b21f1f")
set size ratio 1
set key off
rows = nmeth > 0 ? nmeth : 1

do for [fmt in formats] {
	if (fmt eq "pdf") {
		set terminal pdfcairo size 8, (2.6 * rows + 0.6) font "Helvetica,9"
	} else {
		if (fmt eq "svg") {
			set terminal svg size 900, 260 * rows + 60 font "Helvetica,10"
		} else {
			set terminal pngcairo size 900, 260 * rows + 60 font "Helvetica,10"
		}
	}
	set output outdir . '/extremes.' . fmt
	set multiplot layout rows, 2 title sprintf("extremes: log10 error_rel on the exponent grid (%s set); x: a cell whose status is not ok", heatset) noenhanced
	do for [i = 1:rows] {
		m = nmeth > 0 ? mnames[i] : "none"
		do for [d = 2:3] {
			set title sprintf("%s, %dD", m, d) noenhanced
			set xlabel (d == 2 ? "eps of body 1" : "eps1 of body 1")
			set ylabel (d == 2 ? "eps of body 2" : "eps2 of body 1")
			stats data using (pick(d, m) ? 1 : 0) nooutput name "CELLS"
			if (CELLS_sum == 0) { set label 1 sprintf("no %dD rows\nfor this method", d) at 0, 0 center front }
			plot data using (pick(d, m) ? xof(d) : NaN):(yof(d)):(lerr(column("error_rel"))) \
				with points pt 5 ps 2.2 palette, \
				'' using (bad(d, m) ? xof(d) : NaN):(yof(d)) with points pt 2 ps 1.5 lc rgb "black"
			unset label 1
		}
	}
	unset multiplot
	unset output
}
