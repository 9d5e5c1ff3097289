# validation.gp - the numerical validation (paper Sec. 6.1) per trial.
#
# Reads only the validation driver's CSV and draws, for 2D and 3D, the
# per-trial mean of e_implicit and of e_gradient (log scale) for each form
# (normal, gradient, and the paper's printed formulas), with the mean over
# the trials of this run in the key and the paper's published means as
# dashed lines. Writes <outdir>/validation.pdf and <outdir>/validation.png.
#
#   gnuplot plots/validation.gp                          (results/validation.csv -> plots/)
#   gnuplot -e "results='results/quick/validation.csv'; outdir='plots/quick'" plots/validation.gp
#
# Run from the top of the project. Values at or below `floor` (exact zeros
# cannot be drawn on a log axis) are drawn at `floor`, and the key says so.

if (!exists("results")) results = 'results/validation.csv'
if (!exists("outdir")) outdir = 'plots'
floor = 1e-22

set datafile separator comma
set datafile columnheaders

# The paper's published means (Sec. 6.1), as the driver recorded them.
call 'plots/sidecar.gp' results 'published_e_implicit_2d' 'pub_imp2'
call 'plots/sidecar.gp' results 'published_e_gradient_2d' 'pub_grad2'
call 'plots/sidecar.gp' results 'published_e_implicit_3d' 'pub_imp3'
call 'plots/sidecar.gp' results 'published_e_gradient_3d' 'pub_grad3'

forms = "normal gradient paper"
form_pt(i) = (i == 1 ? 6 : i == 2 ? 2 : 8)
form_lc(i) = (i == 1 ? '#1b6ca8' : i == 2 ? '#d1495b' : '#6a994e')

sel(d, f, col) = (column("dim") == d && strcol("form") eq f) ? column(col) : NaN
clamp(v) = (v != v) ? NaN : (v > floor ? v : floor)

# Mean and median over the trials of the per-trial means, per dimension,
# form and metric, for the key (the mean is dominated by a few trials); and
# how many points were not finite (counted by the driver, excluded from the
# per-trial means).
do for [d = 2:3] {
	do for [i = 1:3] {
		f = word(forms, i)
		stats results using (sel(d, f, "e_implicit_mean")) nooutput
		eval sprintf("mi_%d_%d = STATS_records > 0 ? STATS_mean : NaN", d, i)
		eval sprintf("di_%d_%d = STATS_records > 0 ? STATS_median : NaN", d, i)
		stats results using (sel(d, f, "e_gradient_mean")) nooutput
		eval sprintf("mg_%d_%d = STATS_records > 0 ? STATS_mean : NaN", d, i)
		eval sprintf("dg_%d_%d = STATS_records > 0 ? STATS_median : NaN", d, i)
		stats results using (sel(d, f, "e_support_mean")) nooutput
		eval sprintf("ms_%d_%d = STATS_records > 0 ? STATS_mean : NaN", d, i)
		stats results using (sel(d, f, "e_support_max")) nooutput
		eval sprintf("xs_%d_%d = STATS_records > 0 ? STATS_max : NaN", d, i)
		stats results using (sel(d, f, "nonfinite_count")) nooutput
		eval sprintf("nf_%d_%d = STATS_records > 0 ? STATS_sum : 0", d, i)
		stats results using (sel(d, f, "e_implicit_max")) nooutput
		eval sprintf("xi_%d_%d = STATS_records > 0 ? STATS_max : NaN", d, i)
		stats results using (sel(d, f, "e_gradient_max")) nooutput
		eval sprintf("xg_%d_%d = STATS_records > 0 ? STATS_max : NaN", d, i)
		stats results using (sel(d, f, "angle_max")) nooutput
		eval sprintf("xa_%d_%d = STATS_records > 0 ? STATS_max : NaN", d, i)
		eval sprintf("nt_%d_%d = STATS_records", d, i)
		stats results using (sel(d, f, "n_points")) nooutput
		eval sprintf("np_%d_%d = STATS_records > 0 ? STATS_sum : 0", d, i)
	}
}
mean_of(kind, d, i) = value(sprintf("%s_%d_%d", kind, d, i))

label_of(kind, d, i) = sprintf("%s: mean %.2e, median %.2e%s", word(forms, i), \
	mean_of("m" . kind, d, i), mean_of("d" . kind, d, i), \
	mean_of("nf", d, i) > 0 ? sprintf(" (%d non-finite pts)", int(mean_of("nf", d, i))) : "")

set logscale y
set format y "10^{%L}"
set xlabel "trial"
set grid ytics lc rgb '#dddddd'
set key top left Left reverse font ",8" spacing 0.9 opaque box lc rgb '#bbbbbb'
set yrange [floor / 10 : 10]

# The same four panels for both terminals.
panels = "\
set multiplot layout 2,2 title sprintf('Numerical validation (paper Sec. 6.1): per-trial means from %s (values below %.0e drawn at %.0e)', results, floor, floor) font ',11'; \
do for [d = 2:3] { \
	set title sprintf('%dD: e_{implicit} = |{/Symbol Y}_2(x_2) - 1|', d); \
	set ylabel 'per-trial mean e_{implicit}'; \
	pub = (d == 2 ? pub_imp2 : pub_imp3); \
	plot for [i = 1:3] results using (column('trial')):(clamp(sel(d, word(forms, i), 'e_implicit_mean'))) \
			with points pt form_pt(i) ps 0.8 lw 1.2 lc rgb form_lc(i) title label_of('i', d, i), \
		pub with lines dt 2 lw 1.5 lc rgb '#444444' title sprintf('published mean %.4e', pub); \
	set title sprintf('%dD: e_{gradient} = |cos(m_1, m_2) + 1|', d); \
	set ylabel 'per-trial mean e_{gradient}'; \
	pub = (d == 2 ? pub_grad2 : pub_grad3); \
	plot for [i = 1:3] results using (column('trial')):(clamp(sel(d, word(forms, i), 'e_gradient_mean'))) \
			with points pt form_pt(i) ps 0.8 lw 1.2 lc rgb form_lc(i) title label_of('g', d, i), \
		pub with lines dt 2 lw 1.5 lc rgb '#444444' title sprintf('published mean %.4e', pub); \
}; \
unset multiplot"

set terminal pdfcairo enhanced color size 11in,8in font "Helvetica,10"
set output outdir . '/validation.pdf'
eval panels
set output

set terminal pngcairo enhanced color size 1600,1150 font "Helvetica,11"
set output outdir . '/validation.png'
eval panels
set output
