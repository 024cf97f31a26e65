# bench -- the benchmarks (make bench; not part of make check).

EXTRA_PROGRAMS += bench/bench-cone bench/bench-modes bench/bench-double \
	bench/bench-stability bench/bench-plan bench/bench-cert \
	bench/bench-compare
bench_bench_cone_SOURCES = bench/bench-cone.c bench/benchutil.c
bench_bench_cone_CPPFLAGS = $(AM_CPPFLAGS) -I$(top_srcdir)/tests
bench_bench_cone_LDADD = $(TEST_LIBS)
bench_bench_modes_SOURCES = bench/bench-modes.c bench/benchutil.c
bench_bench_modes_CPPFLAGS = $(AM_CPPFLAGS) -I$(top_srcdir)/tests
bench_bench_modes_LDADD = $(TEST_LIBS)
bench_bench_double_SOURCES = bench/bench-double.c bench/benchutil.c
bench_bench_double_LDADD = lib/libwc.la
bench_bench_stability_SOURCES = bench/bench-stability.c bench/benchutil.c
bench_bench_stability_LDADD = lib/libwc.la
bench_bench_plan_SOURCES = bench/bench-plan.c bench/benchutil.c
bench_bench_plan_LDADD = lib/libwc.la
bench_bench_cert_SOURCES = bench/bench-cert.c bench/benchutil.c
bench_bench_cert_LDADD = lib/libwc.la
bench_bench_compare_SOURCES = bench/bench-compare.c bench/benchutil.c
bench_bench_compare_LDADD = lib/libwc.la
noinst_HEADERS += bench/benchutil.h
# One batch process against one process per cone (a script: it times the
# program itself).
EXTRA_DIST += bench/bench-batch.sh
BENCH = bench/bench-cone$(EXEEXT) bench/bench-modes$(EXEEXT) \
	bench/bench-double$(EXEEXT) bench/bench-stability$(EXEEXT) \
	bench/bench-plan$(EXEEXT) bench/bench-cert$(EXEEXT) \
	bench/bench-compare$(EXEEXT)
# Against the Parma Polyhedra Library: built only when configure found it.
if WC_HAVE_PPL
EXTRA_PROGRAMS += bench/bench-ppl
bench_bench_ppl_SOURCES = bench/bench-ppl.c bench/benchutil.c
bench_bench_ppl_LDADD = lib/libwc.la $(PPL_LIBS)
BENCH_PPL = bench/bench-ppl$(EXEEXT)
else
BENCH_PPL =
endif
bench: $(BENCH) $(BENCH_PPL) src/wrenchcone$(EXEEXT)
	for b in $(BENCH); do ./$$b || exit 1; done
	@if test -n "$(BENCH_PPL)"; then ./$(BENCH_PPL) || exit 1; else \
	  echo "bench-ppl: skipped: configure did not find the Parma Polyhedra Library (ppl_c.h, -lppl_c; Debian libppl-dev)"; fi
	$(SHELL) $(srcdir)/bench/bench-batch.sh src/wrenchcone$(EXEEXT) $(srcdir)/data
.PHONY: bench
CLEANFILES += $(EXTRA_PROGRAMS)
