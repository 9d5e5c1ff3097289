/* test_tradeoff.c - the tradeoff experiment's draws and SPEC strings:
 *  - every drawn body, written as SPEC text, parses back (mkSpec_Parse, the
 *    command line's own parser) to the same doubles bit for bit, so that a
 *    row's body1/body2 re-create its pair exactly in `mink sum`;
 *  - the draws keep the documented ranges (2D a, b in [1e-3, 10], eps in
 *    [0.1, 1.9]; 3D axes in [1, 10] / [1, 6]), ellipses are eps 1 exactly
 *    where the case says so, and the same (seed, case, trial) gives the
 *    same pair while another trial gives another. */
#include "tradeoff.h"

#include <string.h>

#include "ensure.h"

static int mkSame(const void *a, const void *b, size_t n)
{
	return memcmp(a, b, n) == 0;
}

static void mkTest2(void)
{
	for (int c = 0; c < MK_TRADEOFF_CASES; ++c)
		for (long k = 0; k < 50; ++k) {
			mkBody2 b[2], again[2];
			mkTradeoff_Pair2(7, c, k, &b[0], &b[1]);
			mkTradeoff_Pair2(7, c, k, &again[0], &again[1]);
			ENSURE(mkSame(b, again, sizeof b));
			for (int i = 0; i < 2; ++i) {
				char text[512], msg[256];
				mkSpec spec;
				mkTradeoff_Spec2(b[i], text, sizeof text);
				ENSURE(mkSpec_Parse(text, 2, "body", &spec, msg, sizeof msg) == MK_OK);
				ENSURE(spec.body2.shape.a == b[i].shape.a && spec.body2.shape.b == b[i].shape.b);
				ENSURE(spec.body2.shape.eps == b[i].shape.eps);
				ENSURE(mkSame(&spec.body2.M, &b[i].M, sizeof b[i].M) && mkSame(&spec.body2.t, &b[i].t, sizeof b[i].t));
				ENSURE(b[i].shape.a >= 1e-3 && b[i].shape.a <= 10 && b[i].shape.b >= 1e-3 && b[i].shape.b <= 10);
				int super = i == 0 ? c != MK_TRADEOFF_EE : c == MK_TRADEOFF_SQ;
				ENSURE(super ? b[i].shape.eps >= 0.1 && b[i].shape.eps <= 1.9 : b[i].shape.eps == 1.0);
			}
		}
	mkBody2 x1, x2, y1, y2;
	mkTradeoff_Pair2(7, MK_TRADEOFF_SQ, 0, &x1, &x2);
	mkTradeoff_Pair2(7, MK_TRADEOFF_SQ, 1, &y1, &y2);
	ENSURE(x1.shape.a != y1.shape.a);
}

static void mkTest3(void)
{
	for (int c = 0; c < MK_TRADEOFF_CASES; ++c)
		for (long k = 0; k < 50; ++k) {
			mkBody3 b[2];
			mkTradeoff_Pair3(7, c, k, &b[0], &b[1]);
			for (int i = 0; i < 2; ++i) {
				char text[1024], msg[256];
				mkSpec spec;
				mkTradeoff_Spec3(b[i], text, sizeof text);
				ENSURE(mkSpec_Parse(text, 3, "body", &spec, msg, sizeof msg) == MK_OK);
				mkShape3 s = spec.body3.shape, t = b[i].shape;
				ENSURE(s.a == t.a && s.b == t.b && s.c == t.c && s.eps1 == t.eps1 && s.eps2 == t.eps2);
				ENSURE(mkSame(&spec.body3.M, &b[i].M, sizeof b[i].M) && mkSame(&spec.body3.t, &b[i].t, sizeof b[i].t));
				double amax = i == 0 ? 10.0 : 6.0;
				ENSURE(t.a >= 1 && t.a <= amax && t.b >= 1 && t.b <= amax && t.c >= 1 && t.c <= amax);
				int super = i == 0 ? c != MK_TRADEOFF_EE : c == MK_TRADEOFF_SQ;
				ENSURE(super ? t.eps1 >= 0.1 && t.eps1 <= 1.9 : t.eps1 == 1.0 && t.eps2 == 1.0);
			}
		}
}

int main(void)
{
	mkTest2();
	mkTest3();
	return 0;
}
