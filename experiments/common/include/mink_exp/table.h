/* mink_exp/table.h - a CSV result file read back whole: for the tables,
 * the summaries and the tests.
 *
 * RFC 4180 as mink_exp/csv.h writes it: fields may be quoted ("" is a
 * quote), rows end in "\n" or "\r\n", every row has the header's number of
 * fields. Blank lines (gnuplot's block separators in the geometry files)
 * are not rows: such files are read with mkTable_LoadBlocks.
 *
 * Compressed results. A result "x.csv" may be stored as "x.csv.gz" (large
 * raw results are; Makefile.paper names them): the loaders read gzip files
 * transparently, and a path "x.csv" that does not exist is read from
 * "x.csv.gz" when that does (mkPath_Stored), so a caller names a result by
 * its CSV name whichever way it is stored. */
#ifndef MINK_EXP_TABLE_H
#define MINK_EXP_TABLE_H

#include <stddef.h>

/* cells[r * cols + c] point into buf (unquoted, NUL-terminated); row 0 of
 * the file is the header (names). */
typedef struct mkTable {
	int cols;
	long rows;        /* data rows, header excluded */
	char **names;
	char **cells;
	char *buf;
	int present;      /* 0: missing or malformed (then reported on stderr) */
} mkTable;

/* The file that stores the result `path` into buf: path itself when it
 * exists, else path".gz" when that exists, else path. Its sidecar is
 * "<that file>.meta". */
void mkPath_Stored(const char *path, char *buf, size_t len);

/* Load path into t. A missing file leaves t->present = 0 silently; a
 * malformed one is reported on stderr and treated as missing. */
void mkTable_Load(mkTable *t, const char *path);
/* As mkTable_Load, for the geometry files: blank lines separate blocks of
 * rows; they are dropped, and those after the header counted in *blank. */
void mkTable_LoadBlocks(mkTable *t, const char *path, long *blank);
/* The text of a result already in memory: buf (from malloc, NUL-terminated)
 * becomes the table's, freed by mkTable_Free (or at once when malformed:
 * reported on stderr under `name`, t->present = 0). With blank not NULL the
 * blank lines are dropped and counted as mkTable_LoadBlocks does. */
void mkTable_FromText(mkTable *t, char *buf, const char *name, long *blank);
void mkTable_Free(mkTable *t);
/* The index of the column `name`, or -1. */
int mkTable_Col(const mkTable *t, const char *name);
/* The text of row r, column c ("" when c < 0). */
const char *mkTable_Str(const mkTable *t, long r, int c);
/* A number, NaN when empty or not a number ("nan" reads as NaN). */
double mkTable_Num(const mkTable *t, long r, int c);

#endif
