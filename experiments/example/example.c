/* example.c - one trial of the example experiment (example.h). */
#include "example.h"

#include <stdlib.h>

const char *const mkExample_Columns[] = { "trial", "eps1", "eps2", "n", "e_implicit_max", NULL };

mkResult mkExample_Trial(uint64_t seed, long trial, long n, mkCsv *csv)
{
	mkRng rng;
	mkRng_Seed(&rng, seed, (uint64_t)trial); /* one stream per trial: shards agree */
	const mkShapeRange2 range = { { 1.0, 10.0 }, { 1.0, 10.0 }, { 0.1, 1.9 } };
	mkBody2 b1 = mkBody2_Make(mkDraw_Shape2(&rng, &range), mkDraw_RotShear2(&rng, 1.0, NULL, NULL), (mkVec2){ 0, 0 });
	mkBody2 b2 = mkBody2_Make(mkDraw_Shape2(&rng, &range), mkMat2_Identity(), (mkVec2){ 0, 0 });
	double *buf = malloc(6 * (size_t)n * sizeof *buf);
	if (!buf)
		return MK_ERR_MEMORY;
	double *ux = buf, *uy = buf + n, *x = buf + 2 * n, *y = buf + 3 * n, *kx = buf + 4 * n, *ky = buf + 5 * n;
	mkSumOptions opt = mkSumOptions_Default();
	mkResult rc = mkSample2_Angles((int)n, ux, uy);
	if (rc == MK_OK)
		rc = mkSum2_Batch(b1, b2, &opt, ux, uy, (int)n, x, y, kx, ky);
	double worst = 0.0;
	for (long i = 0; rc == MK_OK && i < n; ++i) {
		mkCheck c = mkCheck2(b1, b2, opt.set, (mkVec2){ x[i], y[i] }, (mkVec2){ kx[i], ky[i] });
		worst = c.e_implicit > worst ? c.e_implicit : worst;
	}
	free(buf);
	if (rc != MK_OK)
		return rc;
	mkCsv_Int(csv, trial);
	mkCsv_Double(csv, b1.shape.eps);
	mkCsv_Double(csv, b2.shape.eps);
	mkCsv_Int(csv, n);
	mkCsv_Double(csv, worst);
	mkCsv_EndRow(csv);
	return MK_OK;
}
