/* sceneprep.c - poses prepared side by side (cspace/sceneprep.h): the
 * portable build of the loops and the choice of a build by the CPU. */
#include "cspace/sceneprep_body.h"

void mkSqPrep_RunScalar(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *spheres, mkSqPrep *out)
{
	mkSqPrep_Body(poses, n, parts, t, half, M, abc, ell, spheres, out);
}

long mkSqPrep_FirstBadScalar(const double *poses, long n)
{
	return mkSqPrep_FirstBadBody(poses, n);
}

uint32_t mkSqPrep_Near(const double *x, const double *y, const double *z, const double *rr, int n, const double c[3])
{
	uint32_t m = 0;
	for (int i = 0; i < n; ++i) {
		double dx = c[0] - x[i], dy = c[1] - y[i], dz = c[2] - z[i];
		m |= (uint32_t)!(dx * dx + dy * dy + dz * dz > rr[i]) << i;
	}
	return m;
}

mkSqPrepFn mkSqPrep_Pick(mkImpl impl)
{
#if defined(MINK_HAVE_X86_KERNELS)
	if (impl == MK_IMPL_AUTO)
		impl = mkImpl_Available(MK_IMPL_AVX512) ? MK_IMPL_AVX512 : mkImpl_Available(MK_IMPL_AVX2) ? MK_IMPL_AVX2
			: MK_IMPL_SCALAR;
	if (impl == MK_IMPL_AVX512 && mkImpl_Available(MK_IMPL_AVX512)) return mkSqPrep_RunAvx512;
	if (impl == MK_IMPL_AVX2 && mkImpl_Available(MK_IMPL_AVX2)) return mkSqPrep_RunAvx2;
#endif
	return impl == MK_IMPL_AUTO || impl == MK_IMPL_SCALAR ? mkSqPrep_RunScalar : NULL;
}

mkSqNearFn mkSqPrep_PickNear(mkImpl impl)
{
	mkSqPrepFn f = mkSqPrep_Pick(impl);
#if defined(MINK_HAVE_X86_KERNELS)
	if (f == mkSqPrep_RunAvx512) return mkSqPrep_NearAvx512;
	if (f == mkSqPrep_RunAvx2) return mkSqPrep_NearAvx2;
#endif
	return f ? mkSqPrep_Near : NULL;
}

mkSqFirstBadFn mkSqPrep_PickFirstBad(mkImpl impl)
{
	mkSqPrepFn f = mkSqPrep_Pick(impl);
#if defined(MINK_HAVE_X86_KERNELS)
	if (f == mkSqPrep_RunAvx512) return mkSqPrep_FirstBadAvx512;
	if (f == mkSqPrep_RunAvx2) return mkSqPrep_FirstBadAvx2;
#endif
	return f ? mkSqPrep_FirstBadScalar : NULL;
}
