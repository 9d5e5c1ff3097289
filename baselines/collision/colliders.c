/* colliders.c - the table of collision algorithms (mink/colliders.h). To add
 * one, define its mkCollider in a file of its own and add one line below. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "colliders_internal.h"

static const mkCollider *const table[] = {
	&mkCollider_MinkNormal,
	&mkCollider_MinkRay,
	&mkCollider_MinkNormalLm,
	&mkCollider_MinkRayLm,
	&mkCollider_CommonNormal,
	&mkCollider_Implicit,
	&mkCollider_GjkPoly,
	&mkCollider_CcdGjk,
	&mkCollider_CcdMpr,
	&mkCollider_CcdGjkEpa,
	&mkCollider_CcdGjkEpa6,
	&mkCollider_CcdGjkEpa8,
	&mkCollider_CcdGjkEpa10,
	&mkCollider_Fcl,
	&mkCollider_Asc,
	&mkCollider_AscEigen,
	&mkCollider_Referee,
};

enum { COUNT = (int)(sizeof table / sizeof table[0]) };

int mkColliders_Count(void)
{
	return COUNT;
}

const mkCollider *mkColliders_At(int i)
{
	return i >= 0 && i < COUNT ? table[i] : NULL;
}

const mkCollider *mkColliders_Find(const char *name)
{
	if (!name)
		return NULL;
	for (int i = 0; i < COUNT; ++i)
		if (strcmp(table[i]->name, name) == 0)
			return table[i];
	return NULL;
}

int mkCollider_Accepts(const mkCollider *c, mkBody3 b1, mkBody3 b2, char *msg, size_t msglen)
{
	if (!c) {
		if (msg && msglen)
			snprintf(msg, msglen, "no collider given");
		return 0;
	}
	if (c->pairs & MK_PAIRS_SUPERQUADRICS)
		return 1;
	const mkBody3 *b[2] = { &b1, &b2 };
	for (int k = 0; k < 2; ++k) {
		if (!mkShape3_IsEllipsoid(b[k]->shape)) {
			if (msg && msglen)
				snprintf(msg, msglen, "%s takes ellipsoids only: body%d has eps1 = %.17g, eps2 = %.17g",
					c->name, k + 1, b[k]->shape.eps1, b[k]->shape.eps2);
			return 0;
		}
	}
	return 1;
}

mkResult mkCollider_Run(const mkCollider *c, mkBody3 b1, mkBody3 b2, mkColliderScratch *scratch, mkCollision3 *out)
{
	if (out)
		mkCollision3_Clear(out);
	if (!c || !scratch || !out)
		return MK_ERR_ARGUMENT;
	if (!mkCollider_Accepts(c, b1, b2, NULL, 0))
		return MK_ERR_UNSUPPORTED;
	if (c->prepare) {
		mkResult r = c->prepare(b1, b2, scratch);
		if (r != MK_OK)
			return r;
	}
	return c->run(b1, b2, scratch, out);
}

void mkCollision3_FromLegacy(mkCollide c, mkCollision3 *out)
{
	out->status = c.collide == 1 ? MK_CONTACT_OVERLAPPING : c.collide == 0 ? MK_CONTACT_SEPARATED : MK_CONTACT_UNKNOWN;
	out->residual = c.residual;
	out->iterations = c.iterations;
}
