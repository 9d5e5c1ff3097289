#!/bin/sh
# example.sh - the worked example of docs/compare.md, exactly as the page
# gives it: an algorithm in Python (docs/compare/support.py) run as an
# external method by `mink sum`, scored by `mink score`, then run through the
# tradeoff study next to two registry methods, its rows re-checked by
# `mink score`, and its curve drawn. Run from the top of the project after
# building (cmake -S . -B build && cmake --build build); WORK (default
# compare-example) receives the files, MINK_BUILD names another build folder.
set -eu
WORK=${1:-compare-example}
build=${MINK_BUILD:-build}   # the build folder (the tests pass theirs)
mink=$build/experiments/mink/mink
mkdir -p "$WORK"

# 1. One call of the algorithm, scored.
B1="superellipse a=3 b=2 eps=0.5 rot=0.3"
B2="ellipse a=1 b=0.5"
$mink sum --dim 2 --method "exec:python3 docs/compare/support.py" --n 64 \
    --body1 "$B1" --body2 "$B2" --out "$WORK/support64.csv"
$mink score --dim 2 --body1 "$B1" --body2 "$B2" --points "$WORK/support64.csv"

# 2. The tradeoff study with it as an external method.
$build/experiments/tradeoff/tradeoff --force --trials 2 --seed 7 --budget 0 --repeats 1 \
    --levels 2d=8,32,128,512 --levels 3d=4,8,16 \
    --methods "closed-normal,hull-qhull,exec:support=python3 docs/compare/support.py" \
    --out "$WORK/tradeoff.csv"

# 3. Its rows re-checked: the points of the first 2D row of `support`, made
#    again and scored, give the row's hausdorff_abs.
row=$(grep '^2,[A-Z]*,support,' "$WORK/tradeoff.csv" | head -n 1)
n=$(echo "$row" | cut -d, -f5)
want=$(echo "$row" | cut -d, -f9)
b1=$(echo "$row" | cut -d'"' -f2)
b2=$(echo "$row" | cut -d'"' -f4)
$mink sum --dim 2 --method "exec:python3 docs/compare/support.py" --n "$n" \
    --body1 "$b1" --body2 "$b2" --out "$WORK/row.csv"
got=$($mink score --dim 2 --body1 "$b1" --body2 "$b2" --points "$WORK/row.csv" --csv | tail -n 1 | cut -d, -f5)
echo "tradeoff row: hausdorff_abs $want; mink score: $got"
[ "$got" = "$want" ]

# 4. The figure, with the algorithm's curve.
gnuplot -e "results='$WORK/tradeoff.csv'; outdir='$WORK'; formats='png'" plots/tradeoff.gp
echo "figure: $WORK/tradeoff.png"
