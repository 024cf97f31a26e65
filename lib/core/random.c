/* random.c -- seeded, reproducible random problems (wrenchcone random).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The distribution is documented in random.h.  Everything here is a
   fixed function of the options: the draws come from our own splitmix64
   and are turned into integers by rejection, never through rand(),
   floating point or anything that differs between platforms.  The order
   of the draws is part of that function, so changing it changes the
   problems every seed names (and the corpus in data/corpus/ says so).  */

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/random.h"
#include "core/randgen.h"

static const slong MASSES[][2] = {{1, 1}, {1, 1}, {2, 1}, {3, 1}, {1, 2},
                                  {7, 3}};
static const slong INERTIAS[][2] = {{1, 1}, {1, 1}, {1, 2}, {2, 1}, {5, 12},
                                    {25, 12}};

void
wc_random_options_init(wc_random_options * opt)
{
    opt->fixels = 3;
    opt->seed = 1;
    opt->degenerate = 0;
    opt->shape = WC_SHAPE_NONE;
    opt->friction = 0;
    fmpq_init(opt->mu_s);
    fmpq_init(opt->mu_k);
}

void
wc_random_options_clear(wc_random_options * opt)
{
    fmpq_clear(opt->mu_s);
    fmpq_clear(opt->mu_k);
}

char *
wc_random_options_str(const wc_random_options * opt)
{
    char * mus = NULL, * muk = NULL, * s = NULL;
    size_t len = 128;

    if (opt->friction)
    {
        mus = fmpq_get_str(NULL, 10, opt->mu_s);
        muk = fmpq_get_str(NULL, 10, opt->mu_k);
        len += strlen(mus) + strlen(muk);
    }
    s = malloc(len);
    if (s != NULL)
    {
        int k = snprintf(s, len, "--fixels=%ld --seed=%" PRIu64 "%s%s",
                         (long) opt->fixels, opt->seed,
                         opt->degenerate ? " --degenerate" : "",
                         opt->shape == WC_SHAPE_DISK ? " --shape=disk"
                         : opt->shape == WC_SHAPE_POLYGON ? " --shape=polygon"
                         : "");

        if (opt->friction && k >= 0 && (size_t) k < len)
            snprintf(s + k, len - (size_t) k, " --friction=%s%s%s", mus,
                     fmpq_equal(opt->mu_s, opt->mu_k) ? "" : ",",
                     fmpq_equal(opt->mu_s, opt->mu_k) ? "" : muk);
    }
    flint_free(mus);
    flint_free(muk);
    return s;
}

int
wc_random_problem(wc_problem_t P, const wc_random_options * opt,
                  wc_error_t err)
{
    wc_rng rng;
    wc_rng * r = &rng;
    slong n, i, planted = 0;
    fmpq line[4];               /* the line of C: a point, a direction */
    char * opts = NULL;
    int status = WC_OK;

    if (opt->fixels < 1 || opt->fixels > WC_RANDOM_MAX_FIXELS)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "the number of "
                            "fixels must be from 1 to %d, not %ld",
                            WC_RANDOM_MAX_FIXELS, (long) opt->fixels);
    if (opt->shape != WC_SHAPE_NONE && opt->shape != WC_SHAPE_DISK
        && opt->shape != WC_SHAPE_POLYGON)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "unknown shape %d",
                            (int) opt->shape);
    if (opt->friction && (fmpq_sgn(opt->mu_s) < 0 || fmpq_sgn(opt->mu_k) < 0))
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "friction must not be negative");
    n = opt->fixels;
    r->s = opt->seed;
    for (i = 0; i < 4; i++)
        fmpq_init(line + i);

    opts = wc_random_options_str(opt);
    if (opts == NULL || (P->name = malloc(strlen(opts) + 8)) == NULL)
    {
        status = WC_EINTERNAL;
        goto cleanup;
    }
    strcpy(P->name, "random ");
    strcat(P->name, opts);

    /* Globals first: wc_problem_add_fixel copies the global friction.  */
    PICK(P->mass, r, MASSES);
    PICK(P->inertia, r, INERTIAS);
    if (opt->friction)
    {
        fmpq_set(P->mu_s, opt->mu_s);
        fmpq_set(P->mu_k, opt->mu_k);
    }
    else
        _wc_random_mu(P->mu_s, P->mu_k, r);
    for (i = 0; i < n; i++)
        if (wc_problem_add_fixel(P) == NULL)
        {
            status = WC_EINTERNAL;
            goto cleanup;
        }

    /* The shape and the centre of mass, then the fixels.  */
    if (opt->shape == WC_SHAPE_DISK)
        status = _wc_random_disk(P, r, opt->degenerate);
    else if (opt->shape == WC_SHAPE_POLYGON)
        status = opt->degenerate ? _wc_random_bent_box(P, r)
            : _wc_random_polygon(P, r);
    else if (_wc_rng_chance(r, 1, 2))
        _wc_random_point(P->com, r, 0);
    if (status != WC_OK)
        goto cleanup;
    if (opt->degenerate)
    {
        if (opt->shape == WC_SHAPE_DISK)
            planted = _wc_random_plant_disk(P, r);
        else if (opt->shape == WC_SHAPE_POLYGON)
            planted = _wc_random_plant_polygon(P, r, line);
        else
            planted = _wc_random_plant_plain(P, r, line);
        for (i = planted; i < n; i++)
            _wc_random_extra_fixel(P, i, r, line);
        /* Fisher-Yates: the features anywhere in the fixel order */
        for (i = n - 1; i > 0; i--)
        {
            slong k = _wc_rng_int(r, 0, i);
            wc_fixel_struct t = P->fixels[i];

            P->fixels[i] = P->fixels[k];
            P->fixels[k] = t;
        }
    }
    else
        for (i = 0; i < n; i++)
            _wc_random_generic_fixel(P, i, r);
    if (opt->shape == WC_SHAPE_POLYGON && _wc_rng_chance(r, 1, 4))
        _wc_random_reverse(P);

    for (i = 0; i < n; i++)
    {
        wc_fixel_struct * f = P->fixels + i;

        f->state = _wc_rng_chance(r, 1, 3) ? WC_NEAR : WC_TOUCHING;
        if (!opt->friction && _wc_rng_chance(r, 1, 5))
            _wc_random_mu(f->mu_s, f->mu_k, r);
    }

cleanup:
    if (status != WC_OK)
        wc_error_set(err, status, NULL, 0, 0, "out of memory");
    free(opts);
    for (i = 0; i < 4; i++)
        fmpq_clear(line + i);
    return status;
}
