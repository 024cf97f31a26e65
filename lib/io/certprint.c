/* certprint.c -- the parts that the certificates of sets print alike.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <flint/fmpz_vec.h>

#include "core/tick.h"
#include "exact/vec3.h"
#include "io/printutil.h"
#include "io/print.h"
#include "io/certprint.h"
#include "check/verify.h"

void
_wc_fprint_scaled(FILE * out, const fmpq * v, slong len)
{
    fmpz_t l, g;
    fmpz * z = _fmpz_vec_init(len + 1);
    slong j;

    fmpz_init(l);
    fmpz_init(g);
    fmpz_one(l);
    for (j = 0; j < len; j++)
        fmpz_lcm(l, l, fmpq_denref(v + j));
    for (j = 0; j < len; j++)
    {
        fmpz_divexact(z + j, l, fmpq_denref(v + j));
        fmpz_mul(z + j, z + j, fmpq_numref(v + j));
    }
    _fmpz_vec_content(g, z, len);
    if (!fmpz_is_zero(g))
        _fmpz_vec_scalar_divexact_fmpz(z, z, len, g);
    _wc_fprint_zvec(out, z, len, 1);
    _fmpz_vec_clear(z, len + 1);
    fmpz_clear(l);
    fmpz_clear(g);
}

void
_wc_fprint_motion(FILE * out, const wc_motion_struct * a, slong n)
{
    fputs("{\"nudot\": ", out);
    wc_fprint_qvec(out, a->nudot, 3, _wc_print_as_json);
    fputs(", \"c\": ", out);
    wc_fprint_qvec(out, a->c, 2 * n, _wc_print_as_json);
    fputc('}', out);
}

void
_wc_fprint_cone_proof(FILE * out, const _wc_cone_proof * cp, slong n)
{
    slong g, f;

    fputs(",\n   \"closure\": [", out);
    for (g = 0; g < cp->ngen; g++)
    {
        if (g > 0)
            fputs(", ", out);
        _wc_fprint_motion(out, cp->closure + g, n);
    }
    fputc(']', out);
    if (cp->motion == NULL)
        return;
    fputs(",\n   \"motions\": [", out);
    for (f = 0; f < cp->nfaces; f++)
    {
        if (f > 0)
            fputs(", ", out);
        if (cp->included[f])
            _wc_fprint_motion(out, cp->motion + f, n);
        else
            fputs("null", out);
    }
    fputc(']', out);
}

void
_wc_fprint_piece_proof(FILE * out, const _wc_piece_proof * pp, slong nexcl,
                       slong n)
{
    slong g, f, j;

    putc('{', out);
    if (pp->c != NULL)
    {
        fputs("\"static\": [", out);
        for (g = 0; g < pp->ngen; g++)
        {
            if (g > 0)
                fputs(", ", out);
            wc_fprint_qvec(out, pp->c + g * 2 * n, 2 * n,
                           _wc_print_as_json);
        }
        fputs("],\n   ", out);
    }
    fputs("\"faces\": [", out);
    for (f = 0; f < pp->nfaces; f++)
    {
        fputs(f > 0 ? ",\n    " : "\n    ", out);
        if (pp->mult[f] == NULL)
        {
            fputs("null", out);
            continue;
        }
        putc('[', out);
        for (j = 0; j < nexcl; j++)
        {
            if (j > 0)
                fputs(", ", out);
            _wc_fprint_scaled(out, pp->mult[f][j], pp->nmult[f][j]);
        }
        putc(']', out);
    }
    fputs("]}", out);
}

int
_wc_cert_tree(_wc_settree * T, fmpz * h, slong nh,
              _wc_settree_classify classify, void * ctx, wc_error_t err)
{
    int status = _wc_settree_build(T, h, nh, classify, ctx, err);

    _fmpz_vec_clear(h, 3 * nh + 3);
    if (status == WC_OK && T->nplanes > WC_CERT_MAX_PLANES)
        status = wc_error_set(err, WC_EINPUT, NULL, 0, 0, "the certificate "
                              "would list %ld planes, and verify reads at "
                              "most %d", (long) T->nplanes,
                              WC_CERT_MAX_PLANES);
    return status;
}

void
_wc_fprint_planes(FILE * out, const _wc_settree * T)
{
    slong i;

    fputs(",\n \"planes\": [", out);
    for (i = 0; i < T->nplanes; i++)
    {
        if (i > 0)
            fputs(", ", out);
        _wc_fprint_zvec(out, T->planes + 3 * i, 3, 1);
    }
    fputc(']', out);
}

int
_wc_fprint_tree(FILE * out, const _wc_settree * T, const char * excluded,
                wc_error_t err)
{
    slong i;

    fprintf(out, ",\n \"tree\": [{\"basis\": [%ld, %ld, %ld]}",
            (long) T->basis[0], (long) T->basis[1], (long) T->basis[2]);
    for (i = 0; i < T->n; i++)
    {
        const _wc_tree_node * v = T->node + i;

        fputs(",\n  ", out);
        switch (v->kind)
        {
        case WC_NODE_EMPTY:
            fputs("null", out);
            break;
        case WC_NODE_SPLIT:
            fprintf(out, "{\"split\": %ld}", (long) v->a);
            break;
        case WC_NODE_NOT_WEAK:
            fputs("{\"in\": false, \"separator\": ", out);
            _wc_fprint_zvec(out, T->sep + 3 * v->a, 3, 1);
            fputc('}', out);
            break;
        default:
            fprintf(out, "{\"in\": %s, \"%s\": %ld, \"%s\": %ld}",
                    _wc_tf(v->kind == WC_NODE_IN), v->kind == WC_NODE_IN
                    ? "piece" : excluded, (long) v->a, v->kind == WC_NODE_IN
                    ? "piece_face" : "cone_face", (long) v->b);
        }
    }
    fputs("]}\n", out);
    return ferror(out) ? wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                      "write error") : WC_OK;
}
