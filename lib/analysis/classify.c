/* classify.c -- one wrench: weak and strong stability (paper Section 7,
   wrenchcone(1), stability) by exact LPs, the motions, and the modes holding it.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Every LP is homogeneous: strict rows become >= 1, and a feasible answer
   is checked against every row exactly before it is believed; so are the
   multipliers (exact/lp.h).  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpq_vec.h>

#include "model/model.h"
#include "exact/lp.h"
#include "analysis/kinematics.h"
#include "analysis/stabmodel.h"
#include "analysis/facesys.h"
#include "analysis/stability.h"

void
wc_classify_init(wc_classify_t R)
{
    slong k;

    memset(R, 0, sizeof(wc_classify_struct));
    for (k = 0; k < 3; k++)
    {
        fmpq_init(R->g + k);
        fmpq_init(R->weak_sep + k);
    }
    R->weak_c = _fmpq_vec_init(1);
    _wc_motion_init(&R->paper, 0);
}

void
wc_classify_clear(wc_classify_t R)
{
    slong i, k;

    for (k = 0; k < 3; k++)
    {
        fmpq_clear(R->g + k);
        fmpq_clear(R->weak_sep + k);
    }
    for (i = 0; i < R->nmodes; i++)
        free(R->modes[i]);
    free(R->modes);
    _fmpq_vec_clear(R->weak_c, 2 * R->n + 1);
    for (i = 0; i < R->nmotions; i++)
        _wc_motion_clear(R->motions + i, R->n);
    flint_free(R->motions);
    _wc_motion_clear(&R->paper, R->n);
    for (i = 0; i < R->nnofaces; i++)
    {
        free(R->nofaces[i].sign);
        _fmpq_vec_clear(R->nofaces[i].mult, R->nofaces[i].nmult);
    }
    flint_free(R->nofaces);
    memset(R, 0, sizeof(wc_classify_struct));
}

static char *
copy_string(const char * s)
{
    char * t = malloc(strlen(s) + 1);

    strcpy(t, s);
    return t;
}

static wc_motion_struct *
add_motion(wc_classify_t R, const char * sign)
{
    wc_motion_struct * a;

    R->motions = flint_realloc(R->motions,
                               sizeof(wc_motion_struct) * (R->nmotions + 1));
    a = R->motions + R->nmotions++;
    _wc_motion_init(a, R->n);
    a->sign = copy_string(sign);
    return a;
}

static void
add_noface(wc_classify_t R, const char * sign, int rot, fmpq * mult,
           slong nmult)
{
    wc_noface_struct * f;

    R->nofaces = flint_realloc(R->nofaces,
                               sizeof(wc_noface_struct) * (R->nnofaces + 1));
    f = R->nofaces + R->nnofaces++;
    f->sign = copy_string(sign);
    f->rotation = rot;
    f->mult = mult;
    f->nmult = nmult;
}

/* ---------------------------------------------------------------------
   Weak stability: a static solution (R->weak_c) or a separator.  */

static int
classify_weak(wc_classify_t R, const _wc_stab_model * m, wc_error_t err)
{
    int r = _wc_stab_weak(R->weak_c, R->weak_sep, m, R->g, err);

    R->weak = r == 1;
    return r < 0 ? WC_EINTERNAL : WC_OK;
}

/* ---------------------------------------------------------------------
   The moving faces.  */

/* n on every touching fixel, u on the near ones (malloc'd).  */
static char *
rest_string(const _wc_stab_model * m)
{
    char * y = malloc(m->n + 1);
    slong k;

    for (k = 0; k < m->n; k++)
        y[k] = m->P->fixels[k].state == WC_TOUCHING ? 'n' : 'u';
    y[m->n] = '\0';
    return y;
}

/* Solve the moving face (y, rot) for R->g: a motion joins R->motions; with
   certificates, a face without one joins R->nofaces.  */
static int
classify_face(wc_classify_t R, const _wc_stab_model * m, const char * y,
              int rot, int certificates, wc_error_t err)
{
    slong n = m->n, k, nmult;
    fmpq nu[3];
    fmpq * c = _fmpq_vec_init(2 * n + 1), * mult = NULL;
    int r;

    for (k = 0; k < 3; k++)
        fmpq_init(nu + k);
    r = _wc_face_solve(nu, c, certificates ? &mult : NULL, &nmult, m, y, y,
                       rot, R->g, err);
    if (r == 1)
    {
        wc_motion_struct * a = add_motion(R, y);

        _wc_qvec_set(a->nudot, nu, 3);
        _wc_qvec_set(a->c, c, 2 * n);
    }
    else if (r == 0 && certificates)
        add_noface(R, y, rot, mult, nmult);
    for (k = 0; k < 3; k++)
        fmpq_clear(nu + k);
    _fmpq_vec_clear(c, 2 * n + 1);
    return r < 0 ? WC_EINTERNAL : WC_OK;
}

typedef struct
{
    wc_classify_struct * R;
    const _wc_stab_model * m;
    int certificates;
    wc_error_struct * err;
}
face_ctx;

static int
visit_face(void * p, const char * y, int rot)
{
    face_ctx * c = p;

    return classify_face(c->R, c->m, y, rot, c->certificates, c->err);
}

/* Every moving face; *paper_found when one other than n..n moves (then
   R->paper is its first motion).  T: the modes when every fixel touches
   (the touching fixels' modes, enumerated once for both uses), or NULL.  */
static int
classify_moving(wc_classify_t R, int * paper_found,
                const _wc_stab_model * m, int certificates,
                const wc_modes_struct * T, wc_error_t err)
{
    face_ctx c;
    slong n = m->n, i;
    int status;

    *paper_found = 0;
    if (m->t == 0)
    {
        /* No contact: the body moves with nudot = M^-1 g unless g = 0.  */
        if (!_wc_qvec_is_zero(R->g, 3))
        {
            char * y = _wc_stab_expand(m, "");
            wc_motion_struct * a = add_motion(R, y);

            free(y);
            for (i = 0; i < 3; i++)
                fmpq_div(a->nudot + i, R->g + i, m->M + i);
        }
        return WC_OK;
    }
    c.R = R;
    c.m = m;
    c.certificates = certificates;
    c.err = err;
    status = T != NULL ? _wc_stab_moving_faces_of(m, T, visit_face, &c, err)
        : _wc_stab_moving_faces(m, visit_face, &c, err);
    /* The faces other than n..n come first: a motion of one holds g in
       W(y).  */
    if (status == WC_OK && R->nmotions > 0
        && !_wc_stab_all_n(m, R->motions[0].sign))
    {
        *paper_found = 1;
        R->paper.sign = copy_string(R->motions[0].sign);
        _wc_qvec_set(R->paper.nudot, R->motions[0].nudot, 3);
        _wc_qvec_set(R->paper.c, R->motions[0].c, 2 * n);
    }
    return status;
}

/* Paper semantics: a string other than n..n whose cone holds g, when no
   face other than n..n moves.  A static solution that leaves a touching
   fixel unloaded holds g in the string with s there; else one LP per
   touching fixel i: nudot in the null space of every touching fixel's
   rows, no force at i.  */
static int
classify_paper(wc_classify_t R, int * paper_found, const _wc_stab_model * m,
               wc_error_t err)
{
    slong n = m->n, i, f;
    char * y, * x;
    int r;

    if (*paper_found || m->t == 0)
        return WC_OK;
    for (i = 0; i < m->t && R->weak; i++)
    {
        f = m->tidx[i];
        if (fmpq_is_zero(R->weak_c + f) && fmpq_is_zero(R->weak_c + n + f))
        {
            *paper_found = 1;
            x = rest_string(m);
            x[f] = 's';
            R->paper.sign = x;
            _wc_qvec_zero(R->paper.nudot, 3);
            _wc_qvec_set(R->paper.c, R->weak_c, 2 * n);
            return WC_OK;
        }
    }
    if (!R->weak && !m->shared)
        return WC_OK;
    y = rest_string(m);
    x = malloc(n + 1);
    for (i = 0, r = 0; i < m->t && r == 0; i++)
    {
        strcpy(x, y);
        x[m->tidx[i]] = 's';
        r = _wc_face_solve(R->paper.nudot, R->paper.c, NULL, NULL, m, y, x,
                           0, R->g, err);
    }
    if (r == 1)
    {
        *paper_found = 1;
        R->paper.sign = x;
        x = NULL;
    }
    free(x);
    free(y);
    return r < 0 ? WC_EINTERNAL : WC_OK;
}

/* ---------------------------------------------------------------------
   The modes holding g.  */

/* The modes holding g: from each Table 1 face y of P, the Table 2
   strings x that switch some of y's loaded letters (l r n) to s, by a
   search that stops at the first switch set without a solution (a larger
   set only removes forces).  */
typedef struct
{
    char ** s;
    slong len, alloc;
}
strlist;

static void
strlist_add(strlist * L, const char * s)
{
    if (L->len == L->alloc)
    {
        L->alloc = 2 * L->alloc + 8;
        L->s = realloc(L->s, sizeof(char *) * L->alloc);
    }
    L->s[L->len] = malloc(strlen(s) + 1);
    strcpy(L->s[L->len++], s);
}

static int
str_cmp(const void * p, const void * q)
{
    return strcmp(*(char * const *) p, *(char * const *) q);
}

/* What the search of one face has learnt: solutions found (each holds g
   for every switch set that avoids the fixels it loads) and switch sets
   without a solution (so is every larger one).  */
typedef struct
{
    slong n, nsol, nbad, asol, abad;
    fmpq * sol;             /* nsol blocks of 3 + 2n: nudot, c */
    char ** bad;            /* x strings without a solution */
}
memo;

static void
memo_init(memo * M, slong n)
{
    memset(M, 0, sizeof(memo));
    M->n = n;
}

static void
memo_clear(memo * M)
{
    slong i;

    if (M->asol > 0)
        _fmpq_vec_clear(M->sol, M->asol * (3 + 2 * M->n));
    for (i = 0; i < M->nbad; i++)
        free(M->bad[i]);
    free(M->bad);
    memset(M, 0, sizeof(memo));
}

static const fmpq *
memo_add_sol(memo * M, const fmpq * nudot, const fmpq * c)
{
    slong w = 3 + 2 * M->n;
    fmpq * b;

    if (M->nsol == M->asol)
    {
        slong na = 2 * M->asol + 4;
        fmpq * v = _fmpq_vec_init(na * w);

        if (M->asol > 0)
        {
            _wc_qvec_set(v, M->sol, M->nsol * w);
            _fmpq_vec_clear(M->sol, M->asol * w);
        }
        M->sol = v;
        M->asol = na;
    }
    b = M->sol + (M->nsol++) * w;
    _wc_qvec_set(b, nudot, 3);
    _wc_qvec_set(b + 3, c, 2 * M->n);
    return b;
}

/* A stored solution that loads no fixel switched to s in x, or NULL.  */
static const fmpq *
memo_sol(const memo * M, const char * x)
{
    slong k, i, n = M->n, w = 3 + 2 * n;

    for (k = 0; k < M->nsol; k++)
    {
        const fmpq * c = M->sol + k * w + 3;

        for (i = 0; i < n; i++)
            if (x[i] == 's' && (!fmpq_is_zero(c + i) || !fmpq_is_zero(c + n + i)))
                break;
        if (i == n)
            return M->sol + k * w;
    }
    return NULL;
}

/* 1 when x switches every fixel some known failure switched.  */
static int
memo_bad(const memo * M, const char * x, const char * y)
{
    slong k, i;

    for (k = 0; k < M->nbad; k++)
    {
        for (i = 0; i < M->n; i++)
            if (M->bad[k][i] == 's' && y[i] != 's' && x[i] != 's')
                break;
        if (i == M->n)
            return 1;
    }
    return 0;
}

/* x holds g with the solution sol = (nudot, c); try switching each loaded
   letter from position from on to s.  A fixel that carries no force in
   the solution switches with the same solution; otherwise the memo may
   answer, and else an LP does.  */
static int
search_modes(strlist * L, slong max, memo * M, const _wc_stab_model * m,
             const char * y, char * x, slong from, const fmpq * g,
             const fmpq * sol, wc_error_t err)
{
    slong i, n = m->n;
    fmpq * own;
    const fmpq * c;
    int r = 1, pass;

    if (max > 0 && L->len >= max)
        return 2;
    strlist_add(L, x);
    /* sol may live in the memo, whose storage moves as it grows */
    own = _fmpq_vec_init(3 + 2 * n);
    _wc_qvec_set(own, sol, 3 + 2 * n);
    sol = own;
    c = own + 3;
    /* Unloaded fixels first (pass 0), then the loaded ones: when the list
       is capped, it fills without LPs.  */
    for (pass = 0; pass < 2; pass++)
    for (i = from; i < n && r == 1; i++)
    {
        char was = x[i];
        int rr, unloaded = fmpq_is_zero(c + i) && fmpq_is_zero(c + n + i);
        const fmpq * s2;

        if (m->P->fixels[i].state != WC_TOUCHING || was == 's'
            || unloaded != (pass == 0))
            continue;
        x[i] = 's';
        if (unloaded)
            rr = search_modes(L, max, M, m, y, x, i + 1, g, sol, err);
        else if ((s2 = memo_sol(M, x)) != NULL)
            rr = search_modes(L, max, M, m, y, x, i + 1, g, s2, err);
        else if (memo_bad(M, x, y))
            rr = 0;
        else
        {
            fmpq nu[3];
            fmpq * cc = _fmpq_vec_init(2 * n + 1);
            slong k;

            for (k = 0; k < 3; k++)
                fmpq_init(nu + k);
            rr = _wc_face_solve(nu, cc, NULL, NULL, m, y, x, 0, g, err);
            if (rr == 1)
                s2 = memo_add_sol(M, nu, cc);
            else if (rr == 0)
            {
                M->bad = realloc(M->bad, sizeof(char *) * (M->nbad + 1));
                M->bad[M->nbad] = malloc(n + 1);
                strcpy(M->bad[M->nbad++], x);
            }
            for (k = 0; k < 3; k++)
                fmpq_clear(nu + k);
            _fmpq_vec_clear(cc, 2 * n + 1);
            if (rr == 1)
                rr = search_modes(L, max, M, m, y, x, i + 1, g, s2, err);
        }
        x[i] = was;
        if (rr < 0 || rr == 2)
            r = rr;
    }
    _fmpq_vec_clear(own, 3 + 2 * n);
    return r;
}

/* T: the problem's modes, or NULL to enumerate them here.  */
static int
classify_modes(wc_classify_t R, const _wc_stab_model * m, slong max,
               const wc_modes_struct * T, wc_error_t err)
{
    wc_modes_t own;
    strlist L = { NULL, 0, 0 };
    fmpq nudot[3];
    fmpq * c = _fmpq_vec_init(2 * m->n + 1);
    char * x = malloc(m->n + 1);
    slong i, k;
    int status, r;

    for (k = 0; k < 3; k++)
        fmpq_init(nudot + k);
    wc_modes_init(own);
    if (T == NULL)
    {
        status = wc_modes_enumerate(own, m->P, err);
        T = own;
    }
    else
        status = WC_OK;
    R->modes_complete = 1;
    for (i = 0; i < T->count && status == WC_OK && R->modes_complete; i++)
    {
        strcpy(x, T->modes[i]);
        r = _wc_face_solve(nudot, c, NULL, NULL, m, T->modes[i], x, 0, R->g,
                           err);
        if (r == 1)
        {
            memo M;
            fmpq * own = _fmpq_vec_init(3 + 2 * m->n);

            memo_init(&M, m->n);
            _wc_qvec_set(own, nudot, 3);
            _wc_qvec_set(own + 3, c, 2 * m->n);
            memo_add_sol(&M, nudot, c);
            r = search_modes(&L, max, &M, m, T->modes[i], x, 0, R->g, own,
                             err);
            memo_clear(&M);
            _fmpq_vec_clear(own, 3 + 2 * m->n);
        }
        if (r < 0)
            status = WC_EINTERNAL;
        else if (r == 2)
            R->modes_complete = 0;
    }
    if (status == WC_OK)
    {
        if (L.len > 1)
            qsort(L.s, L.len, sizeof(char *), str_cmp);
        R->modes = malloc(sizeof(char *) * (L.len + 1));
        R->nmodes = 0;
        for (i = 0; i < L.len; i++)
            if (R->nmodes > 0 && strcmp(R->modes[R->nmodes - 1], L.s[i]) == 0)
                free(L.s[i]);
            else
                R->modes[R->nmodes++] = L.s[i];
        L.len = 0;
    }
    for (i = 0; i < L.len; i++)
        free(L.s[i]);
    free(L.s);
    wc_modes_clear(own);
    for (k = 0; k < 3; k++)
        fmpq_clear(nudot + k);
    _fmpq_vec_clear(c, 2 * m->n + 1);
    free(x);
    return status;
}

int
wc_classify(wc_classify_t R, const wc_problem_t P, const fmpq * g,
            int certificates, slong max_modes, wc_error_t err)
{
    _wc_stab_model m;
    wc_modes_t T;
    slong n;
    int status, paper_found = 0, shared_modes;

    wc_classify_clear(R);
    wc_classify_init(R);
    if ((status = wc_problem_check(P, err)) != WC_OK
        || (status = wc_problem_check_fixels(P, WC_CLASSIFY_MAX_TOUCHING, 1,
                                             "classify", err)) != WC_OK)
        return status;
    n = P->n;
    _wc_stab_model_init(&m, P);
    R->n = n;
    _fmpq_vec_clear(R->weak_c, 1);
    R->weak_c = _fmpq_vec_init(2 * n + 1);
    _wc_motion_clear(&R->paper, 0);
    _wc_motion_init(&R->paper, n);
    _wc_qvec_set(R->g, g, 3);
    /* When every fixel touches, the moving faces and the modes come from
       one enumeration.  */
    wc_modes_init(T);
    shared_modes = m.t == n && n > 0;

    if ((status = classify_weak(R, &m, err)) == WC_OK
        && (!shared_modes
            || (status = wc_modes_enumerate(T, P, err)) == WC_OK)
        && (status = classify_moving(R, &paper_found, &m, certificates,
                                     shared_modes ? T : NULL, err))
        == WC_OK)
    {
        R->strong = R->weak && R->nmotions == 0;
        status = classify_paper(R, &paper_found, &m, err);
    }
    if (status == WC_OK)
    {
        R->strong_paper = !paper_found;
        R->paper_vacuous = (m.t == 0);
        status = classify_modes(R, &m, max_modes, shared_modes ? T : NULL,
                                err);
    }
    wc_modes_clear(T);
    _wc_stab_model_clear(&m);
    return status;
}
