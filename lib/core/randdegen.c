/* randdegen.c -- the degenerate layouts of random problems.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Each plants the features of random.h in fixels 0, 1, ... and returns
   how many fixels it used.  */

#include "core/randgen.h"

static const slong SMALL_SCALES[][2] = {{1, 1}, {2, 1}, {1, 2}, {3, 2}};
static const slong LINE_STEPS[][2] = {{-1, 1}, {2, 1}, {1, 2}, {-1, 2},
                                      {3, 1}};

/* No shape: S and N at one point q, P at fixel 2, C at fixel 3.  The
   line of C (through q and fixel 2's point) goes to line[0..1] (point)
   and line[2..3] (direction) for the extra fixels.  */
slong
_wc_random_plant_plain(wc_problem_struct * P, wc_rng * r, fmpq * line)
{
    slong n = P->n;
    wc_fixel_struct * f = P->fixels;
    wc_qvec2 u, w, d;
    fmpq_t s;

    _wc_qvec2_init(&u);
    _wc_qvec2_init(&w);
    _wc_qvec2_init(&d);
    fmpq_init(s);

    /* fixel 0 at q with normal u */
    _wc_random_point(f[0].point, r, 0);
    do
    {
        fmpq_set_si(u.v + 0, _wc_rng_int(r, -3, 3), 1);
        fmpq_set_si(u.v + 1, _wc_rng_int(r, -3, 3), 1);
    }
    while (_wc_qvec2_is_zero(u.v));
    if (n == 1)
    {
        /* O: the normal line through the centre of mass, pushing at it */
        PICK(s, r, SMALL_SCALES);
        fmpq_neg(s, s);
        _wc_qvec2_addmul(f[0].point, P->com, s, u.v);
        _wc_qvec2_set(f[0].normal, u.v);
        goto done;
    }
    _wc_random_face_com(u.v, r, f[0].point, P->com);
    PICK(s, r, SMALL_SCALES);
    _wc_qvec2_scale(f[0].normal, u.v, s);

    /* fixel 1: S and N, the same point, normal s (u + 10^-9 u^perp) */
    _wc_qvec2_set(f[1].point, f[0].point);
    _wc_qvec2_perp(w.v, u.v);
    if (_wc_rng_chance(r, 1, 2))
        _wc_qvec2_neg(w.v, w.v);
    fmpq_set_si(s, 1, GIGA);
    _wc_qvec2_addmul(f[1].normal, u.v, s, w.v);
    PICK(s, r, SMALL_SCALES);
    _wc_qvec2_scale(f[1].normal, f[1].normal, s);
    if (n == 2)
        goto done;

    /* fixel 2: P, normal +-u at a new point: on the normal line of fixel 0
       (facing it, when opposed) or elsewhere */
    if (_wc_rng_chance(r, 1, 2))
    {
        PICK(s, r, SMALL_SCALES);
        _wc_qvec2_scale(d.v, u.v, s);
    }
    else
        do
            _wc_random_point(d.v, r, 0);
        while (_wc_qvec2_is_zero(d.v));
    fmpq_one(s);
    _wc_qvec2_addmul(f[2].point, f[0].point, s, d.v);
    PICK(s, r, SMALL_SCALES);
    if (_wc_rng_chance(r, 1, 2))
        fmpq_neg(s, s);
    _wc_qvec2_scale(f[2].normal, u.v, s);
    _wc_qvec2_set(line + 0, f[0].point);
    _wc_qvec2_set(line + 2, d.v);
    if (n == 3)
        goto done;

    /* fixel 3: C, on the line through q and fixel 2, a new point */
    PICK(s, r, LINE_STEPS);
    _wc_qvec2_addmul(f[3].point, f[0].point, s, d.v);
    _wc_random_normal(f[3].normal, r);
    _wc_random_face_com(f[3].normal, r, f[3].point, P->com);

done:
    _wc_qvec2_clear(&u);
    _wc_qvec2_clear(&w);
    _wc_qvec2_clear(&d);
    fmpq_clear(s);
    return n < 4 ? n : 4;
}

/* The bent box: S and N at the bend V1, P inside the bottom-left edge,
   C at the corner V0.  The line of C is the bottom edge's.  */
slong
_wc_random_plant_polygon(wc_problem_struct * P, wc_rng * r, fmpq * line)
{
    slong n = P->n;
    wc_fixel_struct * f = P->fixels;
    fmpq_t s;

    fmpq_init(s);
    _wc_qvec2_set(f[0].point, _wc_random_vertex(P, 1));
    _wc_random_edge_normal(f[0].normal, P, 0);
    if (n >= 2)
    {
        _wc_qvec2_set(f[1].point, _wc_random_vertex(P, 1));
        _wc_random_edge_normal(f[1].normal, P, 1);
    }
    if (n >= 3)
    {
        PICK(s, r, _wc_edge_params);
        _wc_random_edge_fixel(f + 2, P, 0, s);
    }
    if (n >= 4)
    {
        _wc_qvec2_set(f[3].point, _wc_random_vertex(P, 0));
        _wc_random_edge_normal(f[3].normal, P,
                               _wc_rng_chance(r, 1, 2) ? 0 : 4);
    }
    _wc_qvec2_set(line + 0, _wc_random_vertex(P, 0));
    fmpq_one(line + 2);
    fmpq_zero(line + 3);
    fmpq_clear(s);
    return n < 4 ? n : 4;
}

/* The disk: fixel 0 anywhere, P its antipode, N its point turned by the
   parameter 1/(2 10^9).  */
slong
_wc_random_plant_disk(wc_problem_struct * P, wc_rng * r)
{
    slong n = P->n;
    wc_fixel_struct * f = P->fixels;
    const fmpq * c = P->shape_data;

    _wc_random_disk_fixel(f + 0, P, r, 0);
    if (n >= 2)
    {
        _wc_qvec2_sub(f[1].point, c, f[0].point);
        fmpq_add(f[1].point + 0, f[1].point + 0, c + 0);
        fmpq_add(f[1].point + 1, f[1].point + 1, c + 1);
        _wc_qvec2_neg(f[1].normal, f[0].normal);
    }
    if (n >= 3)
    {
        wc_qvec2 q, e, w;
        fmpq_t t;

        _wc_qvec2_init(&q);
        _wc_qvec2_init(&e);
        _wc_qvec2_init(&w);
        fmpq_init(t);
        fmpq_set_si(t, _wc_rng_chance(r, 1, 2) ? 1 : -1, 2 * (ulong) GIGA);
        _wc_unit_circle_point(e.v, t);
        _wc_qvec2_sub(q.v, f[0].point, c);           /* r q0 */
        _wc_qvec2_rotate(w.v, q.v, e.v);                  /* r q2 */
        fmpq_add(f[2].point + 0, c + 0, w.v + 0);
        fmpq_add(f[2].point + 1, c + 1, w.v + 1);
        _wc_qvec2_neg(f[2].normal, w.v);
        _wc_qvec2_clear(&q);
        _wc_qvec2_clear(&e);
        _wc_qvec2_clear(&w);
        fmpq_clear(t);
    }
    return n < 3 ? n : 3;
}

/* Fixel i (beyond the planted ones) of a degenerate layout: one of four
   kinds (random.h), drawn generically instead if it would repeat an
   earlier fixel.  */
void
_wc_random_extra_fixel(wc_problem_struct * P, slong i, wc_rng * r,
                       const fmpq * line)
{
    wc_fixel_struct * f = P->fixels + i;
    const wc_fixel_struct * g = P->fixels + _wc_rng_int(r, 0, i - 1);
    slong kind = _wc_rng_int(r, 0, 3);
    fmpq_t s;

    fmpq_init(s);
    if (P->shape == WC_SHAPE_DISK)
    {
        const fmpq * c = P->shape_data;

        if (kind == 0)
        {
            /* the antipode of g */
            _wc_qvec2_sub(f->point, c, g->point);
            fmpq_add(f->point + 0, f->point + 0, c + 0);
            fmpq_add(f->point + 1, f->point + 1, c + 1);
            _wc_qvec2_neg(f->normal, g->normal);
        }
        else if (kind == 1)
        {
            /* g turned by +-1/(2 10^9) on the parametrisation */
            wc_qvec2 e, w;

            _wc_qvec2_init(&e);
            _wc_qvec2_init(&w);
            fmpq_set_si(s, _wc_rng_chance(r, 1, 2) ? 1 : -1, 2 * (ulong) GIGA);
            _wc_unit_circle_point(e.v, s);
            _wc_qvec2_rotate(w.v, g->normal, e.v);
            _wc_qvec2_set(f->normal, w.v);
            _wc_qvec2_sub(f->point, c, w.v);
            _wc_qvec2_clear(&e);
            _wc_qvec2_clear(&w);
        }
        else
            _wc_random_disk_fixel(f, P, r, 0);
    }
    else if (P->shape == WC_SHAPE_POLYGON)
    {
        if (kind == 0)
        {
            /* inside the top edge: opposed to the bottom-left edge */
            PICK(s, r, _wc_edge_params);
            _wc_random_edge_fixel(f, P, 3, s);
        }
        else if (kind == 1)
        {
            /* a vertex, with the normal of one of its edges */
            slong k = _wc_rng_int(r, 0, P->shape_len / 2 - 1);

            _wc_qvec2_set(f->point, _wc_random_vertex(P, k));
            _wc_random_edge_normal(f->normal, P,
                                   _wc_rng_chance(r, 1, 2) ? k : k - 1);
        }
        else if (kind == 2)
        {
            /* on the line of C: inside the bottom-left edge */
            PICK(s, r, _wc_edge_params);
            _wc_random_edge_fixel(f, P, 0, s);
        }
        else
            _wc_random_polygon_fixel(f, P, r, 0);
    }
    else
    {
        if (kind == 0)
        {
            /* g's normal or its opposite, scaled, at a new point */
            _wc_random_point(f->point, r, 0);
            PICK(s, r, SMALL_SCALES);
            if (_wc_rng_chance(r, 1, 2))
                fmpq_neg(s, s);
            _wc_qvec2_scale(f->normal, g->normal, s);
        }
        else if (kind == 1)
        {
            /* g's point, g's normal turned by 90 or 180 degrees */
            slong turn = _wc_rng_int(r, 0, 2);

            _wc_qvec2_set(f->point, g->point);

            if (turn == 0)
                _wc_qvec2_neg(f->normal, g->normal);
            else
            {
                _wc_qvec2_perp(f->normal, g->normal);
                if (turn == 2)
                    _wc_qvec2_neg(f->normal, f->normal);
            }
        }
        else if (kind == 2)
        {
            /* on the line of C */
            _wc_random_coord(s, r, 4);
            _wc_qvec2_addmul(f->point, line, s, line + 2);
            _wc_random_normal(f->normal, r);
            _wc_random_face_com(f->normal, r, f->point, P->com);
        }
        else
            _wc_random_plain_fixel(f, P, r, 0);
    }
    fmpq_clear(s);
    if (_wc_random_repeats(P, i))
        _wc_random_generic_fixel(P, i, r);
}

