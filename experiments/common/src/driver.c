/* driver.c - the harness of the experiment drivers. */
#define _POSIX_C_SOURCE 200809L

#include "mink_exp/driver.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

const char *const mkFlag_SetNames[2] = { "contact", "plus" };

#define MK_FLAGS_MAX 64

/* ---- options ------------------------------------------------------------- */

static int mkFlag_Store(mkFlag *f, const char *value, char *msg, size_t msglen)
{
	int choice = 0;
	switch (f->kind) {
	case MK_FLAG_SWITCH:
		*(int *)f->value = 1;
		return 0;
	case MK_FLAG_LONG:
		return mkArg_Long(f->name, value, (long)f->lo, (long)f->hi, (long *)f->value, msg, msglen);
	case MK_FLAG_DOUBLE:
		return mkArg_Double(f->name, value, f->lo, f->hi, "a number", (double *)f->value, msg, msglen);
	case MK_FLAG_U64:
		return mkArg_U64(f->name, value, (uint64_t *)f->value, msg, msglen);
	case MK_FLAG_CHOICE:
		if (mkArg_Choice(f->name, value, f->choices, f->choice_count, &choice, msg, msglen) != 0)
			return -1;
		*(int *)f->value = choice;
		return 0;
	case MK_FLAG_PATH:
		return mkArg_Path(f->name, value, (const char **)f->value, msg, msglen);
	case MK_FLAG_IMPL:
		return mkArg_Impl(f->name, value, (int *)f->value, msg, msglen);
	case MK_FLAG_TEXT:
	case MK_FLAG_REPEAT:
		if (f->parse) {
			char why[768] = "";
			if (f->parse(f->value, value, why, sizeof why) != 0) {
				snprintf(msg, msglen, "%s = '%s' %s", f->name, value, why);
				return -1;
			}
		} else {
			*(const char **)f->value = value;
		}
		return 0;
	}
	return -1;
}

int mkFlags_Parse(mkFlag *flags, int count, int argc, char **argv, char *msg, size_t msglen)
{
	mkOption opts[MK_FLAGS_MAX];
	if (count > MK_FLAGS_MAX) {
		snprintf(msg, msglen, "too many options declared (%d > %d)", count, MK_FLAGS_MAX);
		return -1;
	}
	for (int i = 0; i < count; ++i) {
		opts[i].name = flags[i].name;
		opts[i].takes_value = flags[i].kind != MK_FLAG_SWITCH;
		flags[i].given = 0;
	}
	mkArgs args;
	mkArgs_Begin(&args, argc, argv);
	const char *name, *value;
	mkArgsStep step;
	while ((step = mkArgs_Step(&args, opts, count, &name, &value, msg, msglen)) != MK_ARGS_END) {
		if (step == MK_ARGS_HELP)
			return 1;
		if (step == MK_ARGS_ERROR)
			return -1;
		for (int i = 0; i < count; ++i) {
			if (strcmp(flags[i].name, name) != 0)
				continue;
			if (flags[i].given && flags[i].kind != MK_FLAG_REPEAT && flags[i].kind != MK_FLAG_SWITCH) {
				snprintf(msg, msglen, "option %s is given twice", name);
				return -1;
			}
			flags[i].given += 1;
			if (mkFlag_Store(&flags[i], value, msg, msglen) != 0)
				return -1;
		}
	}
	return 0;
}

void mkFlags_Print(FILE *fp, const mkFlag *flags, int count)
{
	for (int i = 0; i < count; ++i) {
		char head[96];
		snprintf(head, sizeof head, "%s%s%s", flags[i].name, flags[i].arg ? " " : "",
			flags[i].arg ? flags[i].arg : "");
		/* the help text, its lines indented under the first */
		const char *h = flags[i].help ? flags[i].help : "";
		int first = 1;
		do {
			size_t n = strcspn(h, "\n");
			if (first && strlen(head) <= 18)
				fprintf(fp, "  %-18s  %.*s\n", head, (int)n, h);
			else if (first)
				fprintf(fp, "  %s\n%22s%.*s\n", head, "", (int)n, h);
			else
				fprintf(fp, "%22s%.*s\n", "", (int)n, h);
			first = 0;
			h += n;
		} while (*h++ == '\n');
	}
}

/* ---- runs ---------------------------------------------------------------- */

int mkShard_ParseFlag(void *context, const char *text, char *msg, size_t msglen)
{
	char why[512];
	if (mkShard_Parse(text, "--shard", (mkShard *)context, why, sizeof why) == 0)
		return 0;
	/* mkShard_Parse names the flag and the value itself: keep the rest */
	const char *is = strstr(why, "' is ");
	snprintf(msg, msglen, "%s", is ? is + 2 : why);
	return -1;
}

int mkDriver_ColumnCount(const mkDriver *d)
{
	int n = 0;
	while (d->columns[n])
		++n;
	return n;
}

static void mkRun_Help(const mkDriver *d, const mkFlag *flags, int count)
{
	printf("usage: %s [options]\n%s\n\n", d->name, d->purpose);
	mkFlags_Print(stdout, flags, count);
	printf("\nColumns of the CSV:\n ");
	int width = 1, columns = mkDriver_ColumnCount(d);
	for (int c = 0; c < columns; ++c) {
		int n = (int)strlen(d->columns[c]) + 2;
		if (width + n > 78) {
			printf("\n ");
			width = 1;
		}
		printf(" %s%s", d->columns[c], c + 1 < columns ? "," : "\n");
		width += n;
	}
	if (d->notes)
		printf("%s\n", d->notes);
	printf("Progress goes to stderr when it is a terminal (MINK_PROGRESS=always|never).\n");
}

int mkRun_Begin(mkRun *run, const mkDriver *d, mkFlag *flags, int count, int argc, char **argv)
{
	memset(run, 0, sizeof *run);
	run->driver = d;
	run->trials = d->trials;
	run->seed = d->seed;
	run->shard = mkShard_All();
	char default_out[MK_PATH_MAX];
	snprintf(default_out, sizeof default_out, "results/%s.csv", d->name);
	run->out = default_out;

	char trials_help[160], seed_help[160], out_help[256];
	snprintf(trials_help, sizeof trials_help, "trials, 1..%ld (default %ld)", d->trials_max, d->trials);
	snprintf(seed_help, sizeof seed_help, "run seed, 0..2^64-1, decimal or 0x.. (default %llu)",
		(unsigned long long)d->seed);
	snprintf(out_help, sizeof out_help, "output CSV (default results/%s.csv%s%s%s)", d->name,
		d->shared & MK_SHARED_SHARD ? ",\nor results/" : "", d->shared & MK_SHARED_SHARD ? d->name : "",
		d->shared & MK_SHARED_SHARD ? ".shard-I-of-N.csv with --shard" : "");

	mkFlag all[MK_FLAGS_MAX];
	int n = 0;
	for (int i = 0; i < count && n < MK_FLAGS_MAX - 6; ++i)
		all[n++] = flags[i];
	if (d->shared & MK_SHARED_TRIALS)
		all[n++] = (mkFlag)MK_FLAG_LONG("--trials", "T", trials_help, &run->trials, 1, (double)d->trials_max);
	if (d->shared & MK_SHARED_SEED)
		all[n++] = (mkFlag)MK_FLAG_U64("--seed", "S", seed_help, &run->seed);
	if (d->shared & MK_SHARED_SHARD)
		all[n++] = (mkFlag)MK_FLAG_TEXT("--shard", "I/N",
			"run only block I (0-based) of N of the trials", &run->shard, mkShard_ParseFlag);
	all[n++] = (mkFlag)MK_FLAG_PATH("--out", "PATH", out_help, &run->out);
	all[n++] = (mkFlag)MK_FLAG_SWITCH("--force", "replace an existing output file", &run->force);
	all[n++] = (mkFlag)MK_FLAG_SWITCH("--help", "this text", &run->force);

	char msg[1024];
	int parsed = mkFlags_Parse(all, n - 1, argc, argv, msg, sizeof msg);
	for (int i = 0; i < count; ++i)
		flags[i].given = all[i].given;
	if (parsed == 1) {
		mkRun_Help(d, all, n);
		return MK_RUN_HELP;
	}
	if (parsed != 0) {
		fprintf(stderr, "%s: %s\n", d->name, msg);
		return MK_RUN_USAGE;
	}
	int out_given = all[n - 3].given;
	if (run->out == default_out) {
		if (run->shard.count > 1 && !out_given)
			snprintf(run->outbuf, sizeof run->outbuf, "results/%s.shard-%d-of-%d.csv", d->name,
				run->shard.index, run->shard.count);
		else
			snprintf(run->outbuf, sizeof run->outbuf, "%s", default_out);
		run->out = run->outbuf;
	}
	if (mkPath_PrepareOutput(d->name, run->out, run->force) != 0)
		return MK_RUN_FAILED;

	mkMeta_Init(&run->meta, d->name, d->schema_version, argc, argv);
	mkShard_Range(run->shard, run->trials, &run->begin, &run->end);
	if (d->shared & MK_SHARED_SEED)
		mkMeta_SetU64(&run->meta, "seed", run->seed);
	if (d->shared & MK_SHARED_TRIALS)
		mkMeta_SetInt(&run->meta, "trials", run->trials);
	if (d->shared & MK_SHARED_SHARD) {
		char text[64];
		snprintf(text, sizeof text, "%d/%d", run->shard.index, run->shard.count);
		mkMeta_Set(&run->meta, "shard", text);
		snprintf(text, sizeof text, "%ld..%ld", run->begin, run->end - 1);
		mkMeta_Set(&run->meta, "trial_range", run->end > run->begin ? text : "none");
	}
	return MK_RUN_GO;
}

int mkRun_Status(int begin_status)
{
	return begin_status == MK_RUN_HELP ? 0 : begin_status == MK_RUN_USAGE ? 2 : 1;
}

int mkRun_OpenCsv(mkRun *run, long units)
{
	char msg[1024];
	if (mkCsv_Open(&run->csv, run->out, run->driver->columns, mkDriver_ColumnCount(run->driver), msg,
			sizeof msg) != 0) {
		mkRun_Fail(run, "%s", msg);
		return -1;
	}
	run->csv_open = 1;
	mkProgress_Begin(&run->progress, run->driver->name, units);
	return 0;
}

void mkRun_Step(mkRun *run, long steps)
{
	mkProgress_Add(&run->progress, steps);
}

void mkRun_Fail(const mkRun *run, const char *fmt, ...)
{
	char text[2048];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(text, sizeof text, fmt, ap);
	va_end(ap);
	fprintf(stderr, "%s: %s\n", run->driver->name, text);
}

int mkRun_End(mkRun *run, int failed)
{
	if (!run->csv_open) {
		mkMeta_Free(&run->meta);
		return 1;
	}
	mkProgress_End(&run->progress);
	run->csv_open = 0;
	return mkCsv_Finish(&run->csv, &run->meta, failed, run->driver->name);
}

void mkPath_Sibling(const char *out, const char *name, char *buf, size_t len)
{
	size_t n = strlen(out);
	if (n > 7 && strcmp(out + n - 7, ".csv.gz") == 0)
		n -= 7;
	else if (n > 4 && strcmp(out + n - 4, ".csv") == 0)
		n -= 4;
	snprintf(buf, len, "%.*s/%s", (int)n, out, name);
}

int mkRun_OpenSibling(const mkRun *run, const char *name, const char *const *columns, int count, mkCsv *csv)
{
	char msg[1024], path[MK_PATH_MAX];
	mkPath_Sibling(run->out, name, path, sizeof path);
	if (mkPath_MakeParents(path, msg, sizeof msg) != 0 || mkCsv_Open(csv, path, columns, count, msg, sizeof msg) != 0) {
		mkRun_Fail(run, "%s", msg);
		return -1;
	}
	return 0;
}
