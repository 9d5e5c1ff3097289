/* shard.c - shard parsing and the trial blocks. */
#include "mink_exp/shard.h"

#include <stdio.h>

mkShard mkShard_All(void)
{
	mkShard s = { 0, 1 };
	return s;
}

/* Digits only, at most 9 of them (so the value fits an int); returns the
 * number of characters read, 0 on none or too many. */
static int mkReadDigits(const char *p, long *value)
{
	long v = 0;
	int n = 0;
	while (p[n] >= '0' && p[n] <= '9') {
		if (n == 9)
			return 0;
		v = 10 * v + (p[n] - '0');
		++n;
	}
	*value = v;
	return n;
}

int mkShard_Parse(const char *text, const char *flag, mkShard *out, char *msg, size_t msglen)
{
	long i = 0, n = 0;
	int a = mkReadDigits(text, &i);
	int ok = a > 0 && text[a] == '/';
	int b = ok ? mkReadDigits(text + a + 1, &n) : 0;
	ok = ok && b > 0 && text[a + 1 + b] == '\0' && n >= 1 && n <= MK_SHARD_MAX && i < n;
	if (!ok) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "%s = '%s' is not allowed: must be I/N with 1 <= N <= %d and 0 <= I < N",
				flag, text, MK_SHARD_MAX);
		return -1;
	}
	out->index = (int)i;
	out->count = (int)n;
	return 0;
}

void mkShard_Range(mkShard shard, long total, long *begin, long *end)
{
	/* Products stay below 2^63 for total < 2^43 and count <= 10^6. */
	*begin = (long)((long long)shard.index * total / shard.count);
	*end = (long)((long long)(shard.index + 1) * total / shard.count);
}
