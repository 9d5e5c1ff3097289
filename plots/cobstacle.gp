# cobstacle.gp - configuration-space obstacles (paper Sec. 7.1): Fig. 9 and
# the timings of Table 2.
#
# Reads only the cobstacle driver's results: the timing rows <results> and
# the Fig. 9 scene in the directory named like <results> without ".csv"
# (fig9-obstacles.csv.gz, fig9-robot.csv, fig9-slices.csv.gz). Draws
#  (a) the obstacles in the workspace (black) with the robot (blue, enlarged
#      5x in an inset-like corner so that its shape can be seen),
#  (b) the C-obstacles of every obstacle in each drawn C-slice, stacked by
#      the robot's heading (red),
#  (c) the time per C-obstacle boundary point of every level and trial,
#      measured here and published,
# into <outdir>/cobstacle.pdf and <outdir>/cobstacle.png.
#
#   gnuplot plots/cobstacle.gp                          (results/cobstacle.csv -> plots/)
#   gnuplot -e "results='results/quick/cobstacle.csv'; outdir='plots/quick'" plots/cobstacle.gp
#
# Run from the top of the project.

if (!exists("results")) results = 'results/cobstacle.csv'
if (!exists("outdir")) outdir = 'plots'
load 'plots/gz.gp'
geom = (strlen(results) > 4 && results[strlen(results)-3:] eq '.csv') ? results[1:strlen(results)-4] : results
obstacles = gzdata(geom . '/fig9-obstacles.csv.gz')
robotfile = geom . '/fig9-robot.csv'
slices = gzdata(geom . '/fig9-slices.csv.gz')

set datafile separator comma
set datafile columnheaders

# ---- Table 2: per dimension and obstacle count --------------------------
# Levels are read from the rows: the distinct (dim, obstacles) pairs in the
# order they appear (the driver writes each level's trials together).
stats results using (column("dim")) nooutput
nrows = STATS_records
array lvl_dim[64]
array lvl_obs[64]
nlvl = 0
prev = ''
set table $levels
plot results using (sprintf('%d %d %d %d', column("dim"), column("obstacles"), column("points"), column("orientations"))) with table
unset table
nlines = |$levels|
do for [i = 1:nlines] {
	key = $levels[i]
	if (key ne prev && strlen(key) > 0) {
		nlvl = nlvl + 1
		lvl_dim[nlvl] = int(word(key, 1))
		lvl_obs[nlvl] = int(word(key, 2))
		prev = key
	}
}

sel(d, n, col) = (column("dim") == d && column("obstacles") == n) ? column(col) : NaN
pub(d, n, col) = (column("dim") == d && column("obstacles") == n) ? (strcol(col) eq "" ? -1 : column(col)) : NaN

# Per level: trials, time (mean, min, max), time per point, points,
# orientations, non-finite points, published figures (NaN when none).
array tm[nlvl]; array tmin[nlvl]; array tmax[nlvl]; array um[nlvl]; array nt[nlvl]; array cm[nlvl]
array np[nlvl]; array no[nlvl]; array nf[nlvl]; array pt[nlvl]; array pu[nlvl]
do for [l = 1:nlvl] {
	d = lvl_dim[l]; n = lvl_obs[l]
	stats results using (sel(d, n, "total_s")) nooutput
	tm[l] = STATS_mean; tmin[l] = STATS_min; tmax[l] = STATS_max; nt[l] = STATS_records
	stats results using (sel(d, n, "us_per_point")) nooutput
	um[l] = STATS_mean
	stats results using (sel(d, n, "cpu_s")) nooutput
	cm[l] = STATS_mean
	stats results using (sel(d, n, "points")) nooutput
	np[l] = STATS_max
	stats results using (sel(d, n, "orientations")) nooutput
	no[l] = STATS_max
	stats results using (sel(d, n, "nonfinite")) nooutput
	nf[l] = STATS_sum
	# An empty published cell (a level the paper does not list) reads as -1.
	stats results using (pub(d, n, "published_total_s")) nooutput
	pt[l] = STATS_max > 0 ? STATS_max : NaN
	stats results using (pub(d, n, "published_us_per_point")) nooutput
	pu[l] = STATS_max > 0 ? STATS_max : NaN
}


# ---- figure ------------------------------------------------------------
# The drawn headings, for the labels of panel (b).
stats robotfile using (column("heading")) nooutput
hmin = STATS_min
hmax = STATS_max
stats obstacles using (column("obstacle")) nooutput
nobs = int(STATS_max) + 1
stats robotfile using (column("slice")) nooutput
nslices = int(STATS_max) + 1

panels = "\
set multiplot title sprintf('C-obstacles in SE(2) (paper Sec. 7.1, Fig. 9): %d obstacles, %d of the robot headings; timings of Table 2 from %s', nobs, nslices, results) font ',12'; \
unset logscale; set autoscale; \
set origin 0.0, 0.40; set size 0.42, 0.58; \
set title '(a) obstacles in the workspace (black); the robot above, 5x enlarged (blue)' font ',10'; \
set size ratio -1; unset key; \
set xlabel 'x'; set ylabel 'y'; \
set xrange [-220:220]; set yrange [-220:275]; \
set xtics 100; set ytics -200, 100, 200; \
set arrow 1 from -220, 222 to 220, 222 nohead lc rgb '#bbbbbb' dt 2; \
set label 1 'robot, heading 0, 5x' at -20, 248 right font ',9' tc rgb '#1b6ca8'; \
plot obstacles using 'x':'y' with lines lw 0.6 lc rgb 'black', \
     robotfile using (column('slice') == 0 ? 5 * column('x') : NaN):(248 + 5 * column('y')) with lines lw 1.5 lc rgb '#1b6ca8'; \
unset arrow 1; unset label 1; \
set origin 0.42, 0.40; set size 0.58, 0.58; \
set title '(b) C-obstacles obstacle (+) (-robot), one slice per robot heading' font ',10'; \
set size noratio; \
set view 62, 28, 1.0, 1.0; \
set xlabel 'x' offset 0,-1; set ylabel 'y' offset 0,-1; set zlabel 'heading (rad)' rotate parallel offset 1,0; \
set xrange [-220:220]; set yrange [-220:220]; set zrange [hmin - 0.05:hmax + 0.05]; \
set xtics 100 offset 0,-0.5; set ytics 100 offset 0,-0.5; set ztics 0.5; \
set xyplane 0; set border 4095 lc rgb '#888888'; \
splot slices using 'x':'y':'heading' with lines lw 0.3 lc rgb '#d1495b'; \
set border 3 lc rgb 'black'; \
set origin 0.0, 0.0; set size 1.0, 0.40; \
set title 'Table 2: time per C-obstacle boundary point, measured here (each trial a point, label: mean) and published (bars)' font ',10'; \
set key outside right top vertical font ',9'; \
set autoscale y; set ytics autofreq; set logscale y; set yrange [0.005:20]; set format y '%g'; \
set ylabel 'time per point (µs)'; set xlabel 'level'; \
set xrange [0.4:nlvl + 0.6]; \
set xtics () font ',8'; \
do for [l = 1:nlvl] { set xtics add (sprintf('%dD: %d obstacles\n%d points x %d %s', lvl_dim[l], lvl_obs[l], np[l], no[l], lvl_dim[l] == 2 ? 'headings' : 'rotations') l) }; \
do for [l = 1:nlvl] { set label 100 + l sprintf('%.3f µs', um[l]) at l, um[l] * 2.2 center front font ',9' tc rgb '#d1495b' }; \
do for [l = 1:nlvl] { if (pu[l] == pu[l]) { set label 200 + l sprintf('%.3f µs', pu[l]) at l, pu[l] * 1.6 center front font ',9' tc rgb '#555555' } }; \
set style fill solid 1.0 border lc rgb '#666666'; set boxwidth 0.5; \
plot for [l = 1:nlvl] results using (l):(sel(lvl_dim[l], lvl_obs[l], 'published_us_per_point')) \
		with boxes lc rgb '#bbbbbb' title (l == 1 ? 'published (MATLAB, Xeon 2.8 GHz, one core)' : ''), \
	for [l = 1:nlvl] results using (l + 0.08 * (column('trial') - (nt[l] - 1) / 2.0)):(sel(lvl_dim[l], lvl_obs[l], 'us_per_point')) \
		with points pt 7 ps 0.9 lc rgb '#d1495b' title (l == 1 ? 'measured here (one thread), each trial' : ''); \
unset label; unset multiplot"

set terminal pdfcairo enhanced color size 12in,10in font "Helvetica,10"
set output outdir . '/cobstacle.pdf'
eval panels
set output

set terminal pngcairo enhanced color size 1500,1250 font "Helvetica,11"
set output outdir . '/cobstacle.png'
eval panels
set output
