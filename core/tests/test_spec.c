/* test_spec.c - the SPEC grammar: valid bodies parse to the documented map,
 * and every kind of bad input fails with a message that names the field. */
#include <string.h>

#include <mink/mink.h>

#include "ensure.h"

static int fails_with(const char *text, int dim, const char *needle)
{
	mkSpec s;
	char msg[512] = "";
	mkResult r = mkSpec_Parse(text, dim, "body1", &s, msg, sizeof msg);
	if (r == MK_OK) {
		fprintf(stderr, "  '%s' parsed but should fail\n", text);
		return 0;
	}
	if (!strstr(msg, needle)) {
		fprintf(stderr, "  '%s': message '%s' lacks '%s'\n", text, msg, needle);
		return 0;
	}
	return 1;
}

int main(void)
{
	mkSpec s;
	char msg[512];
	ENSURE(mkSpec_Parse("superellipse a=3 b=2 eps=0.5 rot=0.5 shear=2 at=1,-2", 2, "body1", &s, msg, sizeof msg) == MK_OK);
	ENSURE(s.dim == 2 && s.kind == MK_KIND_SUPERELLIPSE);
	ENSURE(s.body2.shape.a == 3 && s.body2.shape.b == 2 && s.body2.shape.eps == 0.5);
	/* M = R(0.5) [1 2; 0 1]: first column (cos, sin), second 2 (cos, sin) + (-sin, cos) */
	ENSURE_NEAR(s.body2.M.m[0][0], cos(0.5), 1e-16);
	ENSURE_NEAR(s.body2.M.m[0][1], 2 * cos(0.5) - sin(0.5), 1e-15);
	ENSURE_NEAR(s.body2.M.m[1][1], 2 * sin(0.5) + cos(0.5), 1e-15);
	ENSURE(s.body2.t.x == 1 && s.body2.t.y == -2);
	ENSURE(mkSpec_Parse("  circle   a=2 ", 2, "body2", &s, msg, sizeof msg) == MK_OK);
	ENSURE(s.body2.shape.a == 2 && s.body2.shape.b == 2 && s.body2.shape.eps == 1);
	ENSURE(mkSpec_Parse("ellipse a=2 b=1 M=1,0.5,0,2", 2, "b", &s, msg, sizeof msg) == MK_OK);
	ENSURE(s.body2.M.m[0][1] == 0.5 && s.body2.M.m[1][1] == 2);
	ENSURE(mkSpec_Parse("superquadric a=1 b=2 c=3 eps1=0.3 eps2=1.7 quat=0,0,0,2 at=1,2,3", 3, "b", &s, msg, sizeof msg) == MK_OK);
	/* quat (0,0,0,1) after normalisation: rotation by pi about z */
	ENSURE_NEAR(s.body3.M.m[0][0], -1.0, 1e-16);
	ENSURE_NEAR(s.body3.M.m[2][2], 1.0, 1e-16);
	ENSURE(s.body3.t.z == 3);
	ENSURE(mkSpec_Parse("sphere a=1", 3, "b", &s, msg, sizeof msg) == MK_OK);
	ENSURE(s.body3.shape.c == 1 && s.body3.shape.eps1 == 1);

	/* mkKind_Name gives the KIND word of the grammar (mink/spec.h), which
	 * parses back to the same kind. */
	static const char *const kinds[] = {"circle a=1", "ellipse a=1 b=2", "superellipse a=1 b=2 eps=0.5",
		"sphere a=1", "ellipsoid a=1 b=2 c=3", "superquadric a=1 b=2 c=3 eps1=0.5 eps2=1.5"};
	for (int k = MK_KIND_CIRCLE; k <= MK_KIND_SUPERQUADRIC; ++k) {
		const char *name = mkKind_Name((mkKind)k);
		size_t len = strlen(name);
		ENSURE(strncmp(kinds[k], name, len) == 0 && kinds[k][len] == ' ');
		ENSURE(mkSpec_Parse(kinds[k], k <= MK_KIND_SUPERELLIPSE ? 2 : 3, "b", &s, msg, sizeof msg) == MK_OK);
		ENSURE(s.kind == (mkKind)k);
	}
	ENSURE(strcmp(mkKind_Name((mkKind)99), "?") == 0);

	ENSURE(fails_with("superellipse a=3 b=2 eps=2.5", 2, "body1.eps"));
	ENSURE(fails_with("superellipse a=3 b=2 eps=0", 2, "body1.eps"));
	ENSURE(fails_with("superellipse a=3 b=2 eps=nan", 2, "body1.eps"));
	ENSURE(fails_with("ellipse a=-1 b=2", 2, "body1.a"));
	ENSURE(fails_with("ellipse a=inf b=2", 2, "body1.a"));
	ENSURE(fails_with("ellipse a=1 b=2 M=1,2,2,4", 2, "body1.M"));
	ENSURE(fails_with("ellipse a=1 b=2 M=1,2,2", 2, "body1.M"));
	ENSURE(fails_with("ellipse a=1 b=2 M=1,0,0,1 rot=1", 2, "M replaces"));
	ENSURE(fails_with("blob a=1", 2, "unknown kind 'blob'"));
	ENSURE(fails_with("sphere a=1", 2, "3D"));
	ENSURE(fails_with("ellipse a=1 b=2 eps=0.5", 2, "key 'eps' is not allowed"));
	ENSURE(fails_with("ellipse a=1", 2, "needs b"));
	ENSURE(fails_with("ellipse a=1 b=", 2, "body1.b: missing value"));
	ENSURE(fails_with("ellipse a=1 b", 2, "key=value"));
	ENSURE(fails_with("ellipse a=1 b=2 a=3", 2, "given twice"));
	ENSURE(fails_with("ellipse a=1x b=2", 2, "body1.a = '1x' is not a number"));
	ENSURE(fails_with("ellipse a=1 b=2 at=1", 2, "body1.at takes 2"));
	ENSURE(fails_with("ellipse a=1 b=2 at=1,nan", 2, "body1.at.y"));
	ENSURE(fails_with("superquadric a=1 b=1 c=1 eps1=1 eps2=1 quat=0,0,0,0", 3, "body1.quat"));
	ENSURE(fails_with("superquadric a=1 b=1 c=1 eps1=1", 3, "needs eps2"));
	ENSURE(fails_with("", 2, "empty SPEC"));
	char longspec[6000];
	memset(longspec, ' ', sizeof longspec - 1);
	longspec[sizeof longspec - 1] = 0;
	ENSURE(fails_with(longspec, 2, "longer than"));
	return mk_summary("test_spec");
}
