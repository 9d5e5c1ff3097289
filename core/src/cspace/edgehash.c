/* edgehash.c - the edge hash of the 3D boundaries: open addressing from
 * 64-bit edge keys (two vertex numbers) to triangle or vertex numbers, with
 * linear probing and removal by tombstone. */
#include "cspace/work.h"

#include <stdlib.h>

uint64_t mkEdgeHash_Undirected(int a, int b)
{
	uint32_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
	return (uint64_t)lo << 32 | hi;
}

uint64_t mkEdgeHash_Directed(int a, int b) { return (uint64_t)(uint32_t)a << 32 | (uint32_t)b; }

static uint64_t mkEdgeHash_Mix(uint64_t z)
{
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	return z ^ (z >> 31);
}

void mkEdgeHash_Clear(mkEdgeHash *h)
{
	h->count = 0;
	for (int i = 0; i < h->cap; ++i) h->val[i] = -1;
}

int mkEdgeHash_Slot(const mkEdgeHash *h, uint64_t k)
{
	if (!h->cap) return -1;
	for (uint64_t i = mkEdgeHash_Mix(k) & (uint64_t)(h->cap - 1);; i = (i + 1) & (uint64_t)(h->cap - 1)) {
		if (h->val[i] == -1) return -1;
		if (h->val[i] >= 0 && h->key[i] == k) return (int)i;
	}
}

int mkEdgeHash_Find(const mkEdgeHash *h, uint64_t k)
{
	int i = mkEdgeHash_Slot(h, k);
	return i < 0 ? -1 : h->val[i];
}

/* The removed entry's slot keeps probing going; the count is not lowered
 * (it decides when the table grows). */
void mkEdgeHash_Remove(mkEdgeHash *h, uint64_t k) { h->val[mkEdgeHash_Slot(h, k)] = -2; }

int mkEdgeHash_Put(mkEdgeHash *h, uint64_t k, int v)
{
	if (2 * (h->count + 1) > h->cap) {
		int nc = h->cap ? 2 * h->cap : 1024;
		uint64_t *nk = malloc((size_t)nc * sizeof *nk);
		int *nv = malloc((size_t)nc * sizeof *nv);
		if (!nk || !nv) { free(nk); free(nv); return 0; }
		for (int i = 0; i < nc; ++i) nv[i] = -1;
		for (int i = 0; i < h->cap; ++i) {
			if (h->val[i] < 0) continue; /* removed entries are dropped */
			uint64_t j = mkEdgeHash_Mix(h->key[i]) & (uint64_t)(nc - 1);
			while (nv[j] >= 0) j = (j + 1) & (uint64_t)(nc - 1);
			nk[j] = h->key[i];
			nv[j] = h->val[i];
		}
		free(h->key); free(h->val);
		h->key = nk; h->val = nv; h->cap = nc;
	}
	uint64_t j = mkEdgeHash_Mix(k) & (uint64_t)(h->cap - 1);
	while (h->val[j] != -1) j = (j + 1) & (uint64_t)(h->cap - 1);
	h->key[j] = k;
	h->val[j] = v;
	++h->count;
	return 1;
}

void mkEdgeHash_Free(mkEdgeHash *h)
{
	free(h->key);
	free(h->val);
	h->key = NULL;
	h->val = NULL;
	h->cap = h->count = 0;
}
