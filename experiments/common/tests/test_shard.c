/* test_shard.c - the shards of a run cover every trial exactly once, in
 * order, in blocks whose sizes differ by at most one; the parser accepts
 * exactly I/N with 0 <= I < N. */
#include "ensure.h"

#include <mink_exp/shard.h>

#include <string.h>

static void mkCheckCover(long total, int count)
{
	static unsigned char seen[5000];
	memset(seen, 0, sizeof seen);
	long expect_begin = 0, smallest = total, largest = 0;
	int ok = 1;
	for (int i = 0; i < count; ++i) {
		mkShard s = { i, count };
		long b, e;
		mkShard_Range(s, total, &b, &e);
		ok = ok && b == expect_begin && e >= b && e <= total;
		for (long t = b; t < e && t < (long)sizeof seen; ++t)
			seen[t] += 1;
		expect_begin = e;
		if (e - b < smallest)
			smallest = e - b;
		if (e - b > largest)
			largest = e - b;
	}
	ok = ok && expect_begin == total && largest - smallest <= 1;
	for (long t = 0; t < total; ++t)
		ok = ok && seen[t] == 1;
	if (!ok)
		fprintf(stderr, "bad cover: total %ld, shards %d\n", total, count);
	ENSURE(ok);
}

int main(void)
{
	for (long total = 0; total <= 250; ++total) {
		for (int count = 1; count <= 64; ++count)
			mkCheckCover(total, count);
	}
	/* More shards than trials, and a paper-sized run over a big array. */
	mkCheckCover(3, 1000);
	mkCheckCover(100, 7);
	mkCheckCover(4999, 997);

	/* Far beyond the test's array: only the block arithmetic. */
	mkShard last = { MK_SHARD_MAX - 1, MK_SHARD_MAX };
	long b, e;
	mkShard_Range(last, 10000000000L, &b, &e);
	ENSURE(e == 10000000000L && e - b == 10000);

	mkShard s;
	char msg[256];
	ENSURE(mkShard_Parse("0/1", "--shard", &s, msg, sizeof msg) == 0 && s.index == 0 && s.count == 1);
	ENSURE(mkShard_Parse("3/4", "--shard", &s, msg, sizeof msg) == 0 && s.index == 3 && s.count == 4);
	ENSURE(mkShard_Parse("999999/1000000", "--shard", &s, msg, sizeof msg) == 0);
	static const char *const bad[] = {
		"", "1", "4/4", "5/4", "-1/4", "1/-4", "0/0", "1/2x", " 1/2", "1 /2", "a/b",
		"1/1000001", "1//2", "+1/2", "1/2/3", "0/99999999999999999999"
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
		msg[0] = '\0';
		int rc = mkShard_Parse(bad[i], "--shard", &s, msg, sizeof msg);
		if (rc == 0)
			fprintf(stderr, "accepted bad shard '%s'\n", bad[i]);
		ENSURE(rc != 0);
		ENSURE(strncmp(msg, "--shard = '", 11) == 0 && strstr(msg, "is not allowed: must be I/N") != NULL);
	}
	return mk_summary("common.test_shard");
}
