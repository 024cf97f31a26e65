/* compare.h -- check a cone computed by someone else's (floating-point)
   code against the exact one (wrenchcone(1), `wrenchcone compare`).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The foreign cone is read from a cddlib file (.ine or .ext, numbers as
   integers, fractions, decimals or exponents) or from our JSON (exact, or
   float with "arith": "double").  Its numbers are read EXACTLY, as the
   rationals they spell, and each representation it gives is turned into
   a canonical closed cone by the exact library; so emptiness, dimension,
   lineality and which extreme rays and facets it has are exact facts
   about the numbers the user wrote.  Floating point enters only where a
   distance is measured: every angle below is computed exactly up to one
   final square root and arctangent in double (the quantities inside, such
   as |v|^2 - |P v|^2 for a projection P, are exact rationals), so tiny
   angles keep their relative accuracy.

   Strictness cannot be compared: a float cone's file cannot be trusted
   to say which faces of its closure are left out, and cdd files cannot
   say it at all.  The comparison is of closures; the report lists the
   faces the exact cone excludes, for the user to check by hand.

   Everything here works in R^3 (the wrench space); cones of another
   dimension are rejected.  */

#ifndef WC_COMPARE_H
#define WC_COMPARE_H

#include <flint/fmpq_mat.h>

#include "core/error.h"
#include "exact/cone.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The default tolerance of `wrenchcone compare`, in radians.  A double
   carries about 16 significant digits, so a cone written with %.17g is
   within about 1e-16 of the exact one; 1e-9 leaves room for the rounding
   of a careful float computation and still catches real mistakes.  */
#define WC_COMPARE_TOL 1e-9

/* ------------------------------------------------------------------ */
/* Angles.  Vectors are 3 rationals; cones are canonical wc_cone_t in R^3.
   "The closure meets the unit sphere nowhere" when the cone is empty or
   {0}; angles to such a set are INFINITY.  */

/* The angle between nonzero a and b, in [0, pi].  */
double wc_angle_vectors(const fmpq * a, const fmpq * b);

/* The angle from v (nonzero) to cl C: min over unit x in cl C of
   angle(v, x); 0 exactly when v lies in cl C, pi/2 or more exactly when
   v lies in the polar cone.  INFINITY when cl C is empty or {0}; NAN when
   v is zero or C is not in R^3.  The face of cl C nearest to v, and
   whether v is inside, are decided exactly.  */
double wc_angle_to_cone(const fmpq * v, const wc_cone_t C);

/* The directed angular distance from cl A to cl B: the largest angle from
   a unit vector of cl A to cl B (0 when cl A is {0}; INFINITY when cl B
   is {0} but cl A is not).  witness (3 doubles, may be NULL) receives a
   unit vector of cl A where it is attained (zeros when cl A is {0}).  Not
   in general at an extreme ray of A: see hausdorff.c.  Exact but for the
   final float conversion, except where part of cl A lies at pi/2 or more
   from cl B: there the value is found among finitely many candidates in
   doubles, and when cl B has more than 48 extreme rays it is only a lower
   bound (still at least pi/2).  Both cones must be nonempty and in R^3.
   Returns WC_OK, WC_EINPUT when a cone is empty or not in R^3, or
   WC_EINTERNAL.  */
int wc_cone_directed_angle(double * dist, double * witness,
                           const wc_cone_t A, const wc_cone_t B,
                           wc_error_t err);

/* The Hausdorff distance between cl A and cl B on the unit sphere, in
   the angular (geodesic) metric: the larger of the two directed
   distances.  0 when both closures are {0}.  Same contract as
   wc_cone_directed_angle.  */
int wc_cone_hausdorff_angle(double * dist, const wc_cone_t A,
                            const wc_cone_t B, wc_error_t err);

/* ------------------------------------------------------------------ */
/* The foreign cone as read.  */

typedef enum
{
    WC_REP_GENERATORS = 0,  /* cdd V-representation; JSON "rays", "lines" */
    WC_REP_INEQUALITIES,    /* cdd H-representation; JSON "inequalities",
                               "equalities" */
    WC_REP_STATED           /* JSON {"empty": true}: no data, only the
                               statement that the cone is empty */
}
wc_rep_kind;

/* One representation of the foreign cone.  */
typedef struct
{
    wc_rep_kind kind;
    long line;          /* where it starts in the file (1-based) */
    int empty;          /* it describes the empty set */
    fmpq_mat_t rows;    /* GENERATORS: rays; INEQUALITIES: normals h of
                           h.g <= 0 (cdd's row 0 a means a.g >= 0: h = -a) */
    fmpq_mat_t lin;     /* GENERATORS: lines; INEQUALITIES: normals e of
                           e.g = 0 */
    long * row_line;    /* the file line of each row of rows, lin */
    long * lin_line;
}
wc_rep_struct;

typedef struct
{
    int json;           /* read from JSON (else a cdd file) */
    int arith_double;   /* JSON "arith": "double" */
    char * mode;        /* JSON "mode" (malloc'd), or NULL */
    slong nreps;        /* 0 (after init), 1 or 2 */
    wc_rep_struct reps[2];
}
wc_foreign_struct;

typedef wc_foreign_struct wc_foreign_t[1];

void wc_foreign_init(wc_foreign_t F);
void wc_foreign_clear(wc_foreign_t F);

/* Read text[0..len) into F (replacing what it held).  A first
   non-blank byte '{' or '[' means JSON, anything else a cdd file; file
   names the text in error records.

   cdd: comment lines start with '*'; before 'begin' come at most one of
   'H-representation' (the default, as in cdd) or 'V-representation' and
   at most one 'linearity k i_1 .. i_k'; the first line of the file may
   also be a name (as lrs writes); then 'begin', 'm 4 numbertype'
   (rational, real or integer; 4 columns: cones live in R^3), m rows of 4
   numbers, one row per line, and 'end'.  A second block (H then V, as
   `wrenchcone cone --format=cdd` writes) may follow: at most one block of
   each kind, a block with no keyword being H.  Rows:
   - H: 'b a1 a2 a3' is b + a.g >= 0 (cdd writes b - A x >= 0 as the row
     b -A).  b must be 0 (a cone), except in a row with a = 0: 'b 0 0 0'
     holds for b >= 0 and is dropped, and with b < 0 (or b != 0 in a
     linearity row) makes the set empty ('-1 0 0 0' is how an empty cone
     is written).  A linearity row is a.g = 0.
   - V: 't x1 x2 x3' is a ray (t = 0; a line when in linearity) or a
     point x / t (t > 0), which must be the origin, the apex '1 0 0 0'.
     A block with no rows at all is the empty set; rays without the apex
     row are read as the cone they generate.  Zero rays are dropped.
   JSON: the output of `wrenchcone cone --format=json` ({"mode", "cone"})
   or a bare CONE object (wrenchcone(1), JSON), exact ("p/q" strings) or float (JSON
   numbers, "arith": "double"); numbers may be either, as strings or
   JSON numbers.  "empty" is required; a nonempty cone needs "rays" (with
   optional "lines") or "inequalities" (with optional "equalities"), and
   each given set is one representation.  Other keys ("dim", "faces",
   "strict", ...) are not read: the dimension is computed from the data,
   and strictness cannot be trusted from a float cone; but "dim",
   "lineality_dim" and "faces", when present, must be well formed
   (dimensions 0 to 3, face ray indices into "rays").

   Limits (hostile files must not take forever): at most 100000 rows in
   a representation, numbers of at most 1000 characters with exponents of
   at most 1000 in absolute value.

   Returns WC_OK; WC_EINPUT with err located FILE:LINE:COL; WC_EINTERNAL
   when out of memory.  On failure F is left as after init.  */
int wc_foreign_parse(wc_foreign_t F, const char * text, size_t len,
                     const char * file, wc_error_t err);

/* ------------------------------------------------------------------ */
/* The comparison.  */

/* One extreme ray or facet normal of one side, compared with the other.  */
typedef struct
{
    double unit[3];     /* the direction, as a unit vector */
    double angle;       /* a ray: its angle to the other side's closure;
                           a facet: NAN (not meaningful) */
    slong nearest;      /* index of the nearest ray (facet) of the other
                           side, -1 when it has none */
    double nearest_angle;   /* the angle to it; INFINITY when none */
    int matched;        /* nearest_angle <= tol */
    long line;          /* foreign: the file line of an input row on this
                           very ray (facet), 0 when none; exact: 0 */
}
wc_cmp_vec;

/* Bits of wc_cmp_rep_struct.differs and wc_comparison_struct.differs.  */
enum
{
    WC_CMP_EMPTY = 1,       /* one side is empty, the other is not */
    WC_CMP_DIM = 2,         /* dimensions of the closures differ */
    WC_CMP_LINEALITY = 4,   /* lineality dimensions differ */
    WC_CMP_DISTANCE = 8,    /* Hausdorff distance above tol */
    WC_CMP_RAYS = 16,       /* an extreme ray is missing or extra */
    WC_CMP_FACETS = 32,     /* a facet is missing or extra */
    WC_CMP_MODE = 64        /* the JSON file is for another mode */
};

/* The comparison of one representation of the foreign cone.  */
typedef struct
{
    wc_rep_kind kind;
    long line;
    wc_cone_t cone;     /* the foreign closure, canonical (exact) */
    slong nrays, nfacets, nexact_rays, nexact_facets;
    wc_cmp_vec * rays;          /* foreign extreme rays; !matched = extra */
    wc_cmp_vec * facets;        /* foreign facets; !matched = extra */
    wc_cmp_vec * exact_rays;    /* the exact cone's; !matched = missing */
    wc_cmp_vec * exact_facets;
    double exact_to_float;  /* directed distances; NAN when either side */
    double float_to_exact;  /* is empty */
    double hausdorff;
    slong nredundant;
    long * redundant;   /* file lines of input rows on no extreme ray
                           (facet) of the foreign closure: inside it,
                           duplicates, or implied */
    unsigned differs;   /* WC_CMP_* */
}
wc_cmp_rep_struct;

typedef struct
{
    double tol;
    int json_file;      /* the foreign cone was read from JSON */
    slong nreps;
    wc_cmp_rep_struct reps[2];
    char * file_mode;   /* the mode a JSON file names, when it is not the
                           mode compared (malloc'd), else NULL */
    unsigned differs;   /* the union over reps, and WC_CMP_MODE */
}
wc_comparison_struct;

typedef wc_comparison_struct wc_comparison_t[1];

void wc_comparison_init(wc_comparison_t R);
void wc_comparison_clear(wc_comparison_t R);

/* Compare the exact cone W of mode (W in R^3, canonical) with every
   representation of F, at tolerance tol (radians, finite, >= 0).  The
   foreign side is within tolerance iff R->differs is 0: the same
   emptiness, dimension and lineality, Hausdorff distance <= tol, and
   every extreme ray and facet of each side within tol of one of the
   other's.  Returns WC_OK (whatever the verdict); WC_EINPUT when tol is
   bad or W is not in R^3; WC_EINTERNAL.  */
int wc_compare(wc_comparison_t R, const wc_cone_t W, const char * mode,
               const wc_foreign_t F, double tol, wc_error_t err);

/* The report, wc_comparison_fprint, is in io/compareprint.h.  */

#ifdef __cplusplus
}
#endif

#endif
