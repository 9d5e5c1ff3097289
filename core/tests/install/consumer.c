/* A program outside the project that uses the installed library. */
#include <math.h>
#include <stdio.h>

#include <mink/mink.h>

int main(void)
{
	mkBody2 a = mkBody2_Make((mkShape2){1, 1, 1}, mkMat2_Identity(), (mkVec2){0, 0});
	mkBody2 b = mkBody2_Make((mkShape2){2, 2, 1}, mkMat2_Identity(), (mkVec2){0, 0});
	mkVec2 x = mkSum2_Point(a, b, MK_SET_CONTACT, MK_FORM_GRADIENT, MK_PARAM_NORMAL, (mkVec2){0, 1}, NULL);
	printf("mink %s: %g %g\n", mkVersion(), x.x, x.y);
	return fabs(x.y - 3.0) < 1e-15 && fabs(x.x) < 1e-15 ? 0 : 1;
}
