// hull_epick.cpp - convex hulls on CGAL's Exact_predicates_inexact_
// constructions_kernel: exact decisions on double coordinates.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "hull_cgal.hpp"

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;

extern "C" mkResult mkHull2_CgalEpick(const double *xy, int count, mkPointSet *out)
{
	return mkcgal::Hull2<Epick>(xy, count, out);
}

extern "C" mkResult mkHull3_CgalEpick(const double *xyz, int count, mkPointSet *out)
{
	return mkcgal::Hull3<Epick>(xyz, count, out);
}
