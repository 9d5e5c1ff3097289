/* spec_keys.h - the SPEC tokenizer and pose parser of spec.c, shared with
 * the scene parser of libmink_cspace (its box and cylinder kinds). Internal
 * to the mink libraries. */
#ifndef MINK_SHAPE_SPEC_KEYS_H
#define MINK_SHAPE_SPEC_KEYS_H

#include <stddef.h>

#include "mink/spec.h"

/* Keys, in the order messages list them; a kind allows a subset. */
typedef enum mkSpecKey {
	MK_SPEC_A, MK_SPEC_B, MK_SPEC_C, MK_SPEC_EPS, MK_SPEC_EPS1, MK_SPEC_EPS2,
	MK_SPEC_SIZE, MK_SPEC_R, MK_SPEC_H,           /* scene kinds: box size=..., cylinder r= h= */
	MK_SPEC_ROT, MK_SPEC_QUAT, MK_SPEC_SHEAR, MK_SPEC_M, MK_SPEC_AT,
	MK_SPEC_KEY_COUNT
} mkSpecKey;

#define MK_SPEC_BIT(k) (1u << (k))
#define MK_SPEC_VALUES_MAX 9

/* The keys given (bit k: key k) and their numbers. */
typedef struct mkSpecValues {
	unsigned seen;
	double val[MK_SPEC_KEY_COUNT][MK_SPEC_VALUES_MAX];
} mkSpecValues;

/* The pose keys of a dimension: 2D rot, shear, M, at; 3D quat, M, at. */
unsigned mkSpecKeys_Pose(int dim);

/* A comma-separated list of numbers: returns how many were given (the first
 * `max` stored in out), -1 when the list is empty, malformed or longer than
 * a SPEC may be. */
int mkSpecKeys_Numbers(const char *s, size_t len, double *out, int max);

/* The names of the keys in mask, comma-separated, into buf. */
void mkSpecKeys_List(unsigned mask, char *buf, size_t len);

/* The key=value tokens of text (the SPEC after its kind) into *v: each key
 * once, in `allow`, with its count of comma-separated numbers (quat 4, M
 * dim^2, at and size dim, else 1). Messages name `what` and, for a key
 * not allowed, `kind` and its allowed keys. MK_OK or MK_ERR_ARGUMENT. */
mkResult mkSpecKeys_Parse(const char *text, int dim, const char *what, const char *kind, unsigned allow,
	mkSpecValues *v, char *msg, size_t msglen);

/* The pose of parsed keys: the map (M, or rot and shear in 2D, or quat in
 * 3D; identity when none is given) and the position `at` (0 when not
 * given). MK_OK, MK_ERR_ARGUMENT (M with rot, shear or quat) or
 * MK_ERR_RANGE (rot, shear or quat out of range), with a message. The
 * caller validates the whole body (mkBody2_IsValid). */
mkResult mkSpecKeys_Pose2(const mkSpecValues *v, const char *what, mkMat2 *M, mkVec2 *t, char *msg, size_t msglen);
mkResult mkSpecKeys_Pose3(const mkSpecValues *v, const char *what, mkMat3 *M, mkVec3 *t, char *msg, size_t msglen);

#endif
