/* jacobi.h - eigen-decomposition of a symmetric 3x3 matrix.
 *
 * The principal axes of a point cloud (the fit's starting pose) come from its
 * scatter matrix; cyclic Jacobi rotations give them to full accuracy without
 * pulling in a linear-algebra library for one 3x3 problem. */
#ifndef MK_FIT_JACOBI_H
#define MK_FIT_JACOBI_H

#include <mink/geom.h>

/* Eigenvalues of the symmetric matrix a (only its upper triangle is read),
 * in ascending order in w[0..2], and the matching unit eigenvectors as the
 * columns of *v, which is a proper rotation (det +1). Returns the number of
 * Jacobi sweeps used, or -1 when the matrix has a non-finite entry or the
 * sweeps do not converge (w and *v then hold NaN). */
int mkSym3_Eigen(mkMat3 a, double w[3], mkMat3 *v);

#endif
