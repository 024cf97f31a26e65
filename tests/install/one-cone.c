/* one-cone.c -- a program outside the tree that uses the installed
   library: the Section 4 example's cone of mode "na", as text.  Built by
   tests/install.sh with pkg-config alone.  */

#include <stdio.h>
#include <string.h>

#include <wrenchcone/wrenchcone.h>

static const char problem[] =
    "mass 1\ninertia 1\ncom 0 0\nfriction 1/5\nshape disk 0 0 1\n"
    "fixel 0 -1 normal 0 1 touching\nfixel 1 0 normal -1 0 near\n";

int
main(void)
{
    wc_problem_t P;
    wc_cone_t W;
    wc_error_t err;
    int status;

    wc_init();
    wc_problem_init(P);
    wc_cone_init(W, 3);
    wc_error_init(err);
    status = wc_problem_parse(P, problem, strlen(problem), "inline", err);
    if (status == WC_OK)
        status = wc_wrench_cone(W, NULL, P, "na", WC_METHOD_DIRECT, err);
    if (status == WC_OK)
    {
        wc_print_opts text = { WC_FORMAT_TEXT, 0, 0, "  " };

        status = wc_cone_fprint(stdout, W, &text);
    }
    else
        fprintf(stderr, "one-cone: %s\n", err->message);
    wc_error_clear(err);
    wc_cone_clear(W);
    wc_problem_clear(P);
    return status == WC_OK ? 0 : 1;
}
