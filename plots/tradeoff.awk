# tradeoff.awk - helper of plots/tradeoff.gp: the medians over the pairs of
# each (dim, case, method, n) of results/tradeoff.csv (awk -F, -v mode=...):
#   mode=names   the methods, in order of first appearance, one per line;
#   mode=points  "dim case method n seconds error" per level, one block
#                per (dim, case, method) (blocks end in a blank line);
#   mode=front   the Pareto front of each (dim, case) over all methods'
#                points: sorted by time, the points whose error is below
#                every faster point's ("dim case seconds error"), one block
#                per (dim, case).
# Columns are found by name in the header; a non-finite error is left out.
# Plain POSIX awk (mawk): no asort.
NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
{
	m = $(col["method"])
	if (!(m in seen)) { seen[m] = 1; names[++nn] = m }
	k = $(col["dim"]) SUBSEP $(col["case"]) SUBSEP m SUBSEP $(col["n"])
	if (!(k in gid)) {
		gid[k] = ++ng; gd[ng] = $(col["dim"]); gc[ng] = $(col["case"]); gm[ng] = m; gn[ng] = $(col["n"])
	}
	g = gid[k]; c = ++cnt[g]
	S[g, c] = $(col["seconds"]) + 0
	e = $(col["hausdorff_rel"])
	E[g, c] = (e ~ /[nN]/) ? -1 : e + 0   # inf, nan: marked, sorted first, see med
}
function med(A, g, n,    i, j, t) {
	for (i = 1; i <= n; ++i) V[i] = A[g, i]
	for (i = 2; i <= n; ++i) { t = V[i]; for (j = i - 1; j >= 1 && V[j] > t; --j) V[j + 1] = V[j]; V[j + 1] = t }
	return n % 2 ? V[(n + 1) / 2] : 0.5 * (V[n / 2] + V[n / 2 + 1])
}
END {
	if (mode == "names") { for (i = 1; i <= nn; ++i) print names[i]; exit }
	for (g = 1; g <= ng; ++g) {
		ms[g] = med(S, g, cnt[g]); bad = 0
		for (i = 1; i <= cnt[g]; ++i) if (E[g, i] < 0) bad = 1
		me[g] = bad ? -1 : med(E, g, cnt[g])
	}
	if (mode == "points") {
		for (g = 1; g <= ng; ++g) {
			if (g > 1 && (gd[g] != gd[g - 1] || gc[g] != gc[g - 1] || gm[g] != gm[g - 1])) print ""
			if (me[g] > 0) printf "%s %s %s %s %.9g %.9g\n", gd[g], gc[g], gm[g], gn[g], ms[g], me[g]
		}
		exit
	}
	for (d = 2; d <= 3; ++d) for (ci = 1; ci <= 3; ++ci) {
		cs = ci == 1 ? "EE" : ci == 2 ? "ES" : "SQ"; np = 0
		for (g = 1; g <= ng; ++g) if (gd[g] == d && gc[g] == cs && me[g] > 0) { ++np; PS[np] = ms[g]; PE[np] = me[g] }
		for (i = 2; i <= np; ++i) {
			t = PS[i]; u = PE[i]
			for (j = i - 1; j >= 1 && PS[j] > t; --j) { PS[j + 1] = PS[j]; PE[j + 1] = PE[j] }
			PS[j + 1] = t; PE[j + 1] = u
		}
		best = -1
		for (i = 1; i <= np; ++i) if (best < 0 || PE[i] < best) { best = PE[i]; printf "%d %s %.9g %.9g\n", d, cs, PS[i], PE[i] }
		if (np > 0) print ""
	}
}
