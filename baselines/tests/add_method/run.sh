#!/bin/sh
# run.sh - add a method to a copy of the sources by the two documented steps
# only (docs/methods.md, "Adding your algorithm"): copy method_support_normal.c
# to baselines/src/ and append its line to baselines/src/registry.def; then
# build the copy and run its whole test suite. The method must appear in
# `mink methods` and pass every test unchanged.
#
#   baselines/tests/add_method/run.sh WORK [JOBS]
#
# WORK is made afresh (the copy is WORK, its build WORK/build); the copy is
# of the files git tracks, as they are in the working tree. Run from the top
# of the project. Exit status: 0 when the suite passes.
set -eu
work=${1:?usage: run.sh WORK [JOBS]}
jobs=${2:-2}
here=baselines/tests/add_method
if [ ! -f "$here/method_support_normal.c" ]; then
	echo "run.sh: run from the top of the project" >&2
	exit 2
fi
rm -rf "$work"
mkdir -p "$work"
git ls-files -z | xargs -0 tar cf - | tar xf - -C "$work"
cp "$here/method_support_normal.c" "$work/baselines/src/"
sed -n 's/^ \*   \(MK_REGISTRY_ENTRY(.*)\)$/\1/p' "$here/method_support_normal.c" >> "$work/baselines/src/registry.def"
tail -n 1 "$work/baselines/src/registry.def"
cmake -S "$work" -B "$work/build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$work/build" -j"$jobs"
"$work/build/experiments/mink/mink" methods | grep '^support-normal '
ctest --test-dir "$work/build" -j"$jobs" --output-on-failure
