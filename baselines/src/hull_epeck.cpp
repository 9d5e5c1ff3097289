// hull_epeck.cpp - convex hulls on CGAL's Exact_predicates_exact_
// constructions_kernel (lazy exact number types).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "hull_cgal.hpp"

typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;

extern "C" mkResult mkHull2_CgalEpeck(const double *xy, int count, mkPointSet *out)
{
	return mkcgal::Hull2<Epeck>(xy, count, out);
}

extern "C" mkResult mkHull3_CgalEpeck(const double *xyz, int count, mkPointSet *out)
{
	return mkcgal::Hull3<Epeck>(xyz, count, out);
}
