/* stability.c -- the weakly and strongly stable wrench sets (paper
   Section 7, wrenchcone(1), stability), exactly, as pieces of the arrangement of their
   cones' planes, and the push regions of each.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The weak set is the closed cone -J (friction cones).  A moving face y
   holds exactly the wrenches of W_y = M V_y + (-J) D_y; the exact strong
   set is the weak set minus their union, the paper's (eq. 19) the
   complement of its own union.  Every cone's planes cut R^3 into cells
   on which each membership is constant, so each set is a union of cells,
   decided at one point of each.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "core/tick.h"
#include "exact/lp.h"
#include "exact/vec3.h"
#include "analysis/kinematics.h"
#include "analysis/stabmodel.h"
#include "analysis/cellset.h"
#include "analysis/stability.h"

void
wc_stability_init(wc_stability_t S)
{
    slong k;

    memset(S, 0, sizeof(wc_stability_struct));
    wc_cone_init(S->weak, 3);
    wc_set_init(S->strong);
    wc_set_init(S->strong_paper);
    for (k = 0; k < 3; k++)
        fmpq_init(S->diff_g + k);
    wc_cells_init(S->cells);
    wc_push_init(S->push_weak);
    wc_push_init(S->push_strong);
    wc_push_init(S->push_strong_paper);
}

void
wc_stability_clear(wc_stability_t S)
{
    slong i, k;

    wc_cone_clear(S->weak);
    wc_set_clear(S->strong);
    wc_set_clear(S->strong_paper);
    for (k = 0; k < 3; k++)
        fmpq_clear(S->diff_g + k);
    for (i = 0; i < S->nmoving; i++)
    {
        wc_cone_clear(S->moving + i);
        free(S->moving_sign[i]);
    }
    flint_free(S->moving);
    flint_free(S->moving_sign);
    flint_free(S->moving_rot);
    for (i = 0; i < S->nunion; i++)
        wc_cone_clear(S->paper_union + i);
    flint_free(S->paper_union);
    wc_cells_clear(S->cells);
    wc_push_clear(S->push_weak);
    wc_push_clear(S->push_strong);
    wc_push_clear(S->push_strong_paper);
    memset(S, 0, sizeof(wc_stability_struct));
}

static void
append_row(fmpq_mat_t A, slong * r, const fmpq * v, int neg)
{
    slong k;

    for (k = 0; k < 3; k++)
        if (neg)
            fmpq_neg(fmpq_mat_entry(A, *r, k), v + k);
        else
            fmpq_set(fmpq_mat_entry(A, *r, k), v + k);
    (*r)++;
}

/* V_y: the rows E nudot = 0 and Z nudot < 0 (Z strict) of the face y
   (rot: rotation face; y = NULL with rot = 1..6: the six pieces of R^3
   minus the origin, no contact).  */
static void
face_rows(fmpq_mat_t E, slong * ne, fmpq_mat_t Z, slong * ns,
          const _wc_stab_model * m, const char * y, int rot)
{
    slong i;
    fmpq e[3];

    if (y == NULL)
    {
        /* piece rot = 2k + 1 or 2k + 2: e_1 .. e_k zero, +-e_{k+1} > 0 */
        slong k = (rot - 1) / 2;

        for (i = 0; i < 3; i++)
            fmpq_init(e + i);
        for (i = 0; i < k; i++)
        {
            _wc_qvec_zero(e, 3);
            fmpq_one(e + i);
            append_row(E, ne, e, 0);
        }
        _wc_qvec_zero(e, 3);
        fmpq_one(e + k);
        append_row(Z, ns, e, (rot - 1) % 2 == 0);
        for (i = 0; i < 3; i++)
            fmpq_clear(e + i);
        return;
    }
    for (i = 0; i < m->n; i++)
    {
        const fmpq * jn = m->Jn + 3 * i, * jt = m->Jt + 3 * i;
        char c = rot != 0 ? 'n' : y[i];

        if (m->P->fixels[i].state != WC_TOUCHING)
            continue;
        switch (c)
        {
        case 's':
            append_row(Z, ns, jn, 1);
            break;
        case 'l':
            append_row(E, ne, jn, 0);
            append_row(Z, ns, jt, 1);
            break;
        case 'r':
            append_row(E, ne, jn, 0);
            append_row(Z, ns, jt, 0);
            break;
        default:
            append_row(E, ne, jn, 0);
            append_row(E, ne, jt, 0);
            break;
        }
    }
    if (rot != 0)
        append_row(Z, ns, m->v, rot > 0);
}

/* W := M V_y + (-J) D_y for the face (y, rot) of face_rows.  */
static int
face_cone(wc_cone_t W, const _wc_stab_model * m, const char * y, int rot,
          wc_error_t err)
{
    slong n = m->n, i, ne = 0, ns = 0;
    fmpq_mat_t E, H, Z, Q, T;
    wc_cone_t V;
    int status;

    fmpq_mat_init(E, 2 * n + 3, 3);
    fmpq_mat_init(H, 0, 3);
    fmpq_mat_init(Z, 2 * n + 3, 3);
    fmpq_mat_init(Q, 0, 3);
    fmpq_mat_init(T, 3, 3);
    for (i = 0; i < 3; i++)
        fmpq_set(fmpq_mat_entry(T, i, i), m->M + i);
    wc_cone_init(V, 3);
    face_rows(E, &ne, Z, &ns, m, y, rot);
    if (y != NULL)
        _wc_stab_edge_rows(Q, m, y, -1);
    _wc_fmpq_mat_keep_rows(E, ne);
    _wc_fmpq_mat_keep_rows(Z, ns);
    status = wc_cone_set_hrep(V, E, H, Z, err);
    if (status == WC_OK)
        status = wc_cone_image_sum(W, T, V, Q, err);
    wc_cone_clear(V);
    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
    fmpq_mat_clear(Z);
    fmpq_mat_clear(Q);
    fmpq_mat_clear(T);
    return status;
}

static wc_cone_struct *
add_moving(wc_stability_t S, const char * sign, int rot)
{
    S->moving = flint_realloc(S->moving,
                              sizeof(wc_cone_struct) * (S->nmoving + 1));
    S->moving_sign = flint_realloc(S->moving_sign,
                                   sizeof(char *) * (S->nmoving + 1));
    S->moving_rot = flint_realloc(S->moving_rot,
                                  sizeof(int) * (S->nmoving + 1));
    wc_cone_init(S->moving + S->nmoving, 3);
    S->moving_sign[S->nmoving] = malloc(strlen(sign) + 1);
    strcpy(S->moving_sign[S->nmoving], sign);
    S->moving_rot[S->nmoving] = rot;
    return S->moving + S->nmoving++;
}

/* Membership in the three sets, straight from the cones.  */
enum { SET_WEAK = 0, SET_STRONG = 1, SET_PAPER = 2 };

typedef struct
{
    const wc_stability_struct * S;
    int which;
}
member_ctx;

static int
in_exact_moving(const wc_stability_struct * S, const fmpq * g)
{
    slong i;

    for (i = 0; i < S->nmoving; i++)
        if (wc_cone_contains(S->moving + i, g))
            return 1;
    return 0;
}

static int
in_paper_union(const wc_stability_struct * S, const fmpq * g)
{
    slong i;

    for (i = 0; i < S->nmoving; i++)
        if (S->moving_rot[i] == 0 && wc_cone_contains(S->moving + i, g))
            return 1;
    for (i = 0; i < S->nunion; i++)
        if (wc_cone_contains(S->paper_union + i, g))
            return 1;
    return 0;
}

static int
member(const fmpq * g, void * p)
{
    const member_ctx * c = p;

    switch (c->which)
    {
    case SET_WEAK:
        return wc_cone_contains(c->S->weak, g);
    case SET_STRONG:
        return wc_cone_contains(c->S->weak, g) && !in_exact_moving(c->S, g);
    default:
        return !in_paper_union(c->S, g);
    }
}

typedef struct
{
    wc_stability_struct * S;
    const _wc_stab_model * m;
    wc_error_struct * err;
}
cone_ctx;

static int
visit_cone(void * p, const char * y, int rot)
{
    cone_ctx * c = p;

    return face_cone(add_moving(c->S, y, rot), c->m, y, rot, c->err);
}

/* The moving faces' cones W_y, with the rotation faces; with no touching
   fixel, the six pieces of R^3 minus the origin.  */
static int
stability_moving(wc_stability_t S, const _wc_stab_model * m, wc_error_t err)
{
    cone_ctx c;
    char * y;
    int k, status = WC_OK;

    if (m->t == 0)
    {
        y = _wc_stab_expand(m, "");
        for (k = 1; k <= 6 && status == WC_OK; k++)
            status = face_cone(add_moving(S, y, 2), m, NULL, k, err);
        free(y);
        return status;
    }
    c.S = S;
    c.m = m;
    c.err = err;
    return _wc_stab_moving_faces(m, visit_cone, &c, err);
}

/* The weak cone -J (friction cones), the moving cones, and eq. 19's extra
   cones: M L0 + (-J) D without fixel i, for each touching fixel i.  */
static int
stability_cones(wc_stability_t S, const _wc_stab_model * m,
                wc_error_t err)
{
    slong n = m->n, i, k;
    fmpq_mat_t Q, L;
    char * y = malloc(n + 1);
    int status;

    fmpq_mat_init(Q, 0, 3);
    fmpq_mat_init(L, 0, 3);
    memset(y, 'n', n);
    y[n] = '\0';
    _wc_stab_edge_rows(Q, m, y, -1);
    status = wc_cone_set_generators(S->weak, Q, NULL, err);
    if (status == WC_OK)
        status = stability_moving(S, m, err);
    if (status == WC_OK && m->t > 0)
    {
        if (m->shared)
        {
            fmpq_mat_clear(L);
            fmpq_mat_init(L, 1, 3);
            for (k = 0; k < 3; k++)
                fmpq_mul(fmpq_mat_entry(L, 0, k), m->v + k, m->M + k);
        }
        S->paper_union = flint_malloc(sizeof(wc_cone_struct) * (m->t + 1));
        for (i = 0; i < m->t && status == WC_OK; i++)
        {
            wc_cone_init(S->paper_union + S->nunion++, 3);
            _wc_stab_edge_rows(Q, m, y, m->tidx[i]);
            status = wc_cone_set_generators(S->paper_union + i, Q, L, err);
        }
    }
    free(y);
    fmpq_mat_clear(Q);
    fmpq_mat_clear(L);
    return status;
}

/* Bit i of the bitset b.  */
#define CELL_BIT(b, i) (((b)[(i) / FLINT_BITS] >> ((i) % FLINT_BITS)) & 1)

/* weak, moving, paper (words words each) := the cells in the weak cone,
   in a moving cone, and in eq. 19's union (the moving cones that are not
   rotation faces, then the union's own cones); a cone at a time over
   every cell, from the cells' signs (cellbits.c).  Returns 0 when out of
   memory.  */
static int
sets_bits(ulong * weak, ulong * moving, ulong * paper,
          const wc_stability_struct * S, wc_cell_bits * X, ulong * buf)
{
    const wc_cells_struct * A = S->cells;
    wc_cone_key * KW = _wc_cone_keys_init(S->weak, 1, A);
    wc_cone_key * KM = _wc_cone_keys_init(S->moving, S->nmoving, A);
    wc_cone_key * KU = _wc_cone_keys_init(S->paper_union, S->nunion, A);
    int ok = KW != NULL && KM != NULL && KU != NULL;

    if (ok)
    {
        _wc_cone_keys_union(weak, KW, 1, NULL, X, A, buf);
        _wc_cone_keys_union(moving, KM, S->nmoving, NULL, X, A, buf);
        _wc_cone_keys_union(paper, KM, S->nmoving, S->moving_rot, X, A,
                            buf);
        _wc_cone_keys_union(paper, KU, S->nunion, NULL, X, A, buf);
    }
    _wc_cone_keys_clear(KW, 1);
    _wc_cone_keys_clear(KM, S->nmoving);
    _wc_cone_keys_clear(KU, S->nunion);
    return ok;
}

/* The cells of all the cones' planes; each set is a union of cells.  A
   cell is in the exact set when it is in the weak cone and in no moving
   cone, and in the paper's set when it is in none of eq. 19's cones.  */
static int
stability_sets(wc_stability_t S, wc_error_t err)
{
    fmpz_mat_t planes;
    slong i, words, np = 0;
    int status, ok, nonzero, * in_exact = NULL, * in_paper = NULL;
    ulong * bits = NULL;
    wc_cell_bits X;

    fmpz_mat_init(planes, 0, 3);
    _wc_cellset_add_planes(planes, &np, S->weak);
    for (i = 0; i < S->nmoving; i++)
        _wc_cellset_add_planes(planes, &np, S->moving + i);
    for (i = 0; i < S->nunion; i++)
        _wc_cellset_add_planes(planes, &np, S->paper_union + i);
    status = WC_OK;
    _wc_cellset_build(S->cells, &status, planes, np, err);
    fmpz_mat_clear(planes);
    if (status != WC_OK)
        return status;
    _wc_tick("cells of the sets", 0, S->cells->count);
    ok = _wc_cell_bits_init(&X, S->cells);
    words = X.words;
    if (ok)
    {
        in_exact = malloc(sizeof(int) * (S->cells->count + 1));
        in_paper = malloc(sizeof(int) * (S->cells->count + 1));
        bits = calloc((size_t) 4 * words + 1, sizeof(ulong));
    }
    ok = ok && in_exact != NULL && in_paper != NULL && bits != NULL
        && sets_bits(bits, bits + words, bits + 2 * words, S, &X,
                     bits + 3 * words);
    _wc_cell_bits_clear(&X);
    S->paper_in_weak = 1;
    S->differ = 0;
    nonzero = 0;
    for (i = 0; ok && i < S->cells->count; i++)
    {
        int w = CELL_BIT(bits, i), z;
        const fmpz * x = WC_ROW(S->cells->point, i);

        in_exact[i] = w && !CELL_BIT(bits + words, i);
        in_paper[i] = !CELL_BIT(bits + 2 * words, i);
        if (in_paper[i] && !w)
            S->paper_in_weak = 0;
        /* The origin is strongly stable by definition and lies in every
           W(x): it differs whenever a fixel touches, which says nothing,
           so a nonzero witness is preferred.  */
        z = _fmpz_vec_is_zero(x, 3);
        if (in_exact[i] != in_paper[i] && (!S->differ || (!nonzero && !z)))
        {
            S->differ = 1;
            nonzero = !z;
            _fmpq_vec_set_fmpz_vec(S->diff_g, x, 3);
            S->diff_in_exact = in_exact[i];
        }
    }
    _wc_tick("cells of the sets", S->cells->count, S->cells->count);
    S->diff_origin_only = S->differ && !nonzero;
    if (!ok)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "out of memory (%ld cells)",
                              (long) S->cells->count);
    else if ((status = wc_set_from_cells(S->strong, S->cells, in_exact, err))
        == WC_OK
        && (status = wc_set_from_cells(S->strong_paper, S->cells, in_paper,
                                       err)) == WC_OK
        && (status = wc_set_merge(S->strong, S->cells, err)) == WC_OK)
        status = wc_set_merge(S->strong_paper, S->cells, err);
    free(bits);
    free(in_exact);
    free(in_paper);
    return status;
}

/* Where a frictionless finger may push, for each set.  */
static int
stability_push(wc_stability_t S, const wc_problem_t P, wc_error_t err)
{
    member_ctx c;
    int status;

    c.S = S;
    S->has_push = 1;
    c.which = SET_WEAK;
    status = wc_push_regions(S->push_weak, P, S->cells->planes, member, &c,
                             err);
    c.which = SET_STRONG;
    if (status == WC_OK)
        status = wc_push_regions(S->push_strong, P, S->cells->planes,
                                 member, &c, err);
    c.which = SET_PAPER;
    if (status == WC_OK)
        status = wc_push_regions(S->push_strong_paper, P,
                                 S->cells->planes, member, &c, err);
    return status;
}

int
wc_stability(wc_stability_t S, const wc_problem_t P, wc_error_t err)
{
    _wc_stab_model m;
    int status;

    wc_stability_clear(S);
    wc_stability_init(S);
    if ((status = wc_problem_check(P, err)) != WC_OK
        || (status = wc_problem_check_fixels(P, WC_STABILITY_MAX_TOUCHING, 1,
                                             "stability", err)) != WC_OK)
        return status;
    _wc_stab_model_init(&m, P);
    S->paper_vacuous = (m.t == 0);
    status = stability_cones(S, &m, err);
    if (status == WC_OK)
        status = stability_sets(S, err);
    if (status == WC_OK && P->shape != WC_SHAPE_NONE)
        status = stability_push(S, P, err);
    _wc_stab_model_clear(&m);
    if (status != WC_OK)
    {
        wc_stability_clear(S);
        wc_stability_init(S);
    }
    return status;
}
