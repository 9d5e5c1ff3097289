# fitting.gp - the fitting errors of paper Sec. 6.2, from the raw rows of
# results/fitting.csv.gz (written by the `fitting` driver); nothing is run.
#   gnuplot plots/fitting.gp                      (results/fitting.csv.gz -> plots/)
#   gnuplot -e "results='results/quick/fitting.csv.gz'; outdir='plots/quick'" plots/fitting.gp
# Run from the top of the project.
# Left: case 2, mean e_volume of the polyhedron against the number of grid
# points, for both samplings, with the paper's three published means.
# Right: cases 1 and 3, mean error per model next to the published figure.
# Error bars are one standard error of the mean (sample std / sqrt(trials)).
# Writes <outdir>/fitting.pdf and <outdir>/fitting.png.

if (!exists("results")) results = "results/fitting.csv.gz"
if (!exists("outdir")) outdir = "plots"
load 'plots/gz.gp'
datafile = gzdata(results)
outbase = outdir . "/fitting"

set datafile separator comma
# columns of the CSV
C_CASE = 1; C_TRUTH = 3; C_MODEL = 4; C_SAMPLING = 5; C_LEVEL = 6
C_EVOL = 10; C_EIMP = 11

# mean and standard error of column `col` over rows matching a filter, into
# the variables M and SE (NaN when no row matches)
M = NaN; SE = NaN
select(c, truth, model, sampling, level) = \
  (column(C_CASE) == c && strcol(C_TRUTH) eq truth && strcol(C_MODEL) eq model \
   && strcol(C_SAMPLING) eq sampling && (level < 0 || column(C_LEVEL) == level))

# ---- case 2: one line per level and sampling --------------------------------
do for [s in "paper distinct"] {
  if (s eq "paper") { set print $PAPER } else { set print $DISTINCT }
  do for [n = 4:20] {
    lev = n * n
    stats datafile skip 1 using (select(2, "superquadric", "polyhedron", s, lev) ? column(C_EVOL) : NaN) nooutput name "S"
    print sprintf("%d %.10g %.10g", lev, S_mean, S_stddev / sqrt(S_records))
  }
  unset print
}

# The paper's published means (Sec. 6.2), as the driver recorded them.
set print $PUBLISHED2
do for [lev in "16 81 400"] {
  call 'plots/sidecar.gp' results 'published_case2_'.lev 'p'
  print sprintf("%s %.10g", lev, p)
}
unset print
array PUB[8]
array PUBKEY[8] = ["case1_e_volume", "case1_e_implicit", "case3_cube_superquadric", \
  "case3_ellipsoid_polyhedron", "", "case3_cylinder_superquadric", "case3_cylinder_polyhedron", ""]
do for [i = 1:8] {
  PUB[i] = NaN
  if (strlen(PUBKEY[i]) > 0) { call 'plots/sidecar.gp' results 'published_'.PUBKEY[i] 'p'; PUB[i] = p }
}

# ---- cases 1 and 3: one entry per model ---------------------------------------
set print $SUMMARY
array LABEL[8] = ["case 1 SQ e_{volume}", "case 1 SQ e_{implicit}", "cube as SQ", \
  "ellipsoid as 9x9 poly", "ellipsoid as 9x9 poly (distinct)", "cylinder as SQ", \
  "cylinder as 2x30 poly", "cylinder as 2x30 poly (distinct)"]
do for [i = 1:8] {
  if (i == 1) { stats datafile skip 1 using (select(1, "polyhedron", "superquadric", "random", -1) ? column(C_EVOL) : NaN) nooutput name "S" }
  if (i == 2) { stats datafile skip 1 using (select(1, "polyhedron", "superquadric", "random", -1) ? column(C_EIMP) : NaN) nooutput name "S" }
  if (i == 3) { stats datafile skip 1 using (select(3, "cube", "superquadric", "none", -1) ? column(C_EVOL) : NaN) nooutput name "S" }
  if (i == 4) { stats datafile skip 1 using (select(3, "ellipsoid", "polyhedron", "paper", -1) ? column(C_EVOL) : NaN) nooutput name "S" }
  if (i == 5) { stats datafile skip 1 using (select(3, "ellipsoid", "polyhedron", "distinct", -1) ? column(C_EVOL) : NaN) nooutput name "S" }
  if (i == 6) { stats datafile skip 1 using (select(3, "cylinder", "superquadric", "none", -1) ? column(C_EVOL) : NaN) nooutput name "S" }
  if (i == 7) { stats datafile skip 1 using (select(3, "cylinder", "polyhedron", "paper", -1) ? column(C_EVOL) : NaN) nooutput name "S" }
  if (i == 8) { stats datafile skip 1 using (select(3, "cylinder", "polyhedron", "distinct", -1) ? column(C_EVOL) : NaN) nooutput name "S" }
  print sprintf("%d %.10g %.10g %.10g", i, S_mean, S_stddev / sqrt(S_records), PUB[i])
}
unset print


set datafile separator whitespace

draw(title2) = 0
do for [term = 1:2] {
  if (term == 1) {
    set terminal pdfcairo size 11in, 4.5in font "Helvetica,10"
    set output outbase . ".pdf"
  } else {
    set terminal pngcairo size 1400, 580 font "Helvetica,10"
    set output outbase . ".png"
  }
  set multiplot layout 1, 2

  set title "Case 2: convex polyhedron fitted to a superquadric"
  set xlabel "points on the superquadric (n x n grid)"
  set ylabel "mean e_{volume} (100 trials)"
  set logscale y
  set format y "10^{%T}"
  set xrange [0:420]
  set yrange [0.01:1]
  set grid
  set key top right
  plot $PAPER using 1:2:3 with yerrorlines lw 2 pt 7 ps 0.6 \
         title "grid of the published code (n-1 distinct longitudes)", \
       $DISTINCT using 1:2:3 with yerrorlines lw 2 pt 5 ps 0.6 \
         title "core grid (n distinct longitudes)", \
       $PUBLISHED2 using 1:2 with points pt 6 ps 2 lw 2 lc rgb "black" title "published (paper, Sec. 6.2)"

  set title "Cases 1 and 3: mean error per model"
  unset xlabel
  set ylabel "mean error"
  set xrange [0.4:8.6]
  set yrange [0.005:1]
  set xtics rotate by 30 right
  set xtics (LABEL[1] 1, LABEL[2] 2, LABEL[3] 3, LABEL[4] 4, LABEL[5] 5, LABEL[6] 6, LABEL[7] 7, LABEL[8] 8)
  set bmargin 10
  set lmargin 12
  set key top right
  plot $SUMMARY using ($1 - 0.12):2:3 with yerrorbars pt 7 ps 1.2 lw 2 title "measured (mean +- std. error)", \
       $SUMMARY using ($1 + 0.12):4 with points pt 6 ps 2 lw 2 lc rgb "black" title "published"

  unset multiplot
  unset output
  unset xtics; set xtics; set bmargin; set lmargin
}
