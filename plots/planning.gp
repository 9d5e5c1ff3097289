# planning.gp - success rate against the time budget, per scene, planner and
# checker, from the rows of results/planning.csv (written by the `planning`
# driver); nothing is run.
#   gnuplot plots/planning.gp                      (results/planning.csv -> plots/)
#   gnuplot -e "results='results/quick/planning.csv'; outdir='plots/quick'" plots/planning.gp
# Run from the top of the project.
# The planners of the experiment stop at their first path, so a run that found
# its path after s seconds would have succeeded with any budget b >= s: the
# curve at b is the fraction of the runs (all trials and queries of the
# scene) with a path found within b. Solid: mink (certified); dashed: FCL
# with OMPL's discrete motion check. Writes <outdir>/planning.pdf and .png.

if (!exists("results")) results = "results/planning.csv"
if (!exists("outdir")) outdir = "plots"
load 'plots/gz.gp'
datafile = gzdata(results)
outbase = outdir . "/planning"

set datafile separator comma
C_SCENE = 3; C_PLANNER = 5; C_CHECKER = 6; C_BUDGET = 7; C_SUCCESS = 10; C_SECONDS = 11
SCENES = "room2d maze2d plate3d home3d passage3d"
PLANNERS = "RRTConnect PRM KPIECE1 RRT"
CHECKERS = "mink fcl"
group(s, p, c) = (strcol(C_SCENE) eq s && strcol(C_PLANNER) eq p && strcol(C_CHECKER) eq c)

stats datafile skip 1 using C_BUDGET nooutput name "B"
budget = B_max

# the groups with runs: scene GS[g], planner GP[g], checker GC[g], GN[g] runs
NMAX = words(SCENES) * words(PLANNERS) * words(CHECKERS)
array GS[NMAX]; array GP[NMAX]; array GC[NMAX]; array GN[NMAX]
NG = 0
do for [i = 1:words(SCENES)] {
  do for [j = 1:words(PLANNERS)] {
    do for [k = 1:words(CHECKERS)] {
      stats datafile skip 1 using (group(word(SCENES, i), word(PLANNERS, j), word(CHECKERS, k)) ? 1 : 0) nooutput name "G"
      if (G_sum > 0) { NG = NG + 1; GS[NG] = i; GP[NG] = j; GC[NG] = k; GN[NG] = G_sum }
    }
  }
}

# a run of group g in scene i that found a path (the other rows add 0 beyond
# the budget: rows with an undefined value would break the cumulative curve)
hit(g, i) = GS[g] == i && group(word(SCENES, i), word(PLANNERS, GP[g]), word(CHECKERS, GC[g])) && column(C_SUCCESS) == 1

do for [term = 1:2] {
  if (term == 1) {
    set terminal pdfcairo size 13in, 8in font "Helvetica,10"
    set output outbase . ".pdf"
  } else {
    set terminal pngcairo size 1650, 1000 font "Helvetica,10"
    set output outbase . ".png"
  }
  set multiplot layout 2, 3
  do for [i = 1:words(SCENES)] {
    s = word(SCENES, i)
    set title sprintf("%s: success rate against the time budget", s)
    set xlabel "time budget (s)"
    set ylabel "fraction of runs with a path"
    set logscale x
    set xrange [0.001:budget]
    set yrange [0:1.05]
    set grid
    set key below horizontal maxrows 2 samplen 2 font ",8"
    set bmargin 6
    plot for [g = 1:NG] datafile skip 1 \
      using (hit(g, i) ? column(C_SECONDS) : 10 * budget):(hit(g, i) ? 1.0 / GN[g] : 0) \
      smooth cumulative with steps lw 2 dashtype GC[g] lc GP[g] \
      title (GS[g] == i ? sprintf("%s, %s (%d runs)", word(PLANNERS, GP[g]), word(CHECKERS, GC[g]), GN[g]) : "")
  }
  unset multiplot
  unset output
}
