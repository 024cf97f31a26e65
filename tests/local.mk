# tests -- C unit and cross-check tests, the independent references they
# compare with, and shell tests of the program.  Everything links the
# convenience library statically: no libtool wrapper between the harness
# and the program under test.
#
# Nor libtool itself: a libtool link costs about a second of CPU more
# than the compiler's, for each of the 33 programs of a fresh make check,
# and a libtool library compiles each file twice.  The references are a
# plain archive, and the tests link the archive libtool makes of the
# convenience library (lib/.libs/libwc.a) with the libraries it needs.

check_LIBRARIES = tests/libwctest.a
tests_libwctest_a_SOURCES = \
	tests/testutil.c tests/testutil.h \
	tests/ref-lp.c tests/ref-lp.h \
	tests/ref-kin.c tests/ref-kin.h \
	tests/old-modes.c tests/old-modes.h \
	tests/ref-stab.c tests/ref-stab.h \
	tests/ref-plan.c tests/ref-plan.h \
	tests/old-faces.c tests/old-faces.h \
	tests/ref-hull3.c tests/ref-hull3.h \
	tests/old-cells.c tests/old-cells.h \
	tests/ref-modes.c tests/ref-modes.h \
	tests/ref-cells.c tests/ref-cells.h \
	tests/ref-faces.c tests/ref-faces.h \
	tests/ref-hausdorff.c tests/ref-hausdorff.h \
	tests/old-hull3.c tests/old-hull3.h

TEST_LIBS = tests/libwctest.a $(WC_ARCHIVE)
WC_ARCHIVE = lib/.libs/libwc.a $(CDD_LIBS) $(FLINT_LIBS) $(GMP_LIBS) \
	$(PTHREAD_LIBS) -lm
# libtool writes the archive when it makes lib/libwc.la
lib/.libs/libwc.a: lib/libwc.la
TEST_LINK = $(CCLD) $(AM_CFLAGS) $(CFLAGS) $(AM_LDFLAGS) $(LDFLAGS) -o $@
C_TESTS = \
	tests/t-plan \
	tests/t-stability \
	tests/t-routes \
	tests/t-modes \
	tests/t-hull3 \
	tests/t-verify \
	tests/t-facesep \
	tests/t-ref \
	tests/t-planbits \
	tests/t-cellsfast \
	tests/t-parse \
	tests/t-model \
	tests/t-cone \
	tests/t-vec3fast \
	tests/t-direct3 \
	tests/t-zrows3 \
	tests/t-modeswalk \
	tests/t-faces \
	tests/t-checkregion \
	tests/t-setcert \
	tests/t-random \
	tests/t-double \
	tests/t-compare \
	tests/t-compare-fast \
	tests/t-cells \
	tests/t-push \
	tests/t-refplan \
	tests/t-plansound \
	tests/t-cellsref \
	tests/t-draw \
	tests/t-request \
	tests/t-decimals \
	tests/t-foreignnum \
	tests/t-threads \
	tests/t-quote
check_PROGRAMS += $(C_TESTS) tests/corpus-check
LDADD = $(TEST_LIBS)
tests_corpus_check_LDADD = $(WC_ARCHIVE)
tests_t_ref_LINK = $(TEST_LINK)
tests_t_parse_LINK = $(TEST_LINK)
tests_t_model_LINK = $(TEST_LINK)
tests_t_cone_LINK = $(TEST_LINK)
tests_t_hull3_LINK = $(TEST_LINK)
tests_t_vec3fast_LINK = $(TEST_LINK)
tests_t_routes_LINK = $(TEST_LINK)
tests_t_direct3_LINK = $(TEST_LINK)
tests_t_zrows3_LINK = $(TEST_LINK)
tests_t_modes_LINK = $(TEST_LINK)
tests_t_modeswalk_LINK = $(TEST_LINK)
tests_t_verify_LINK = $(TEST_LINK)
tests_t_faces_LINK = $(TEST_LINK)
tests_t_checkregion_LINK = $(TEST_LINK)
tests_t_setcert_LINK = $(TEST_LINK)
tests_t_random_LINK = $(TEST_LINK)
tests_t_double_LINK = $(TEST_LINK)
tests_t_compare_LINK = $(TEST_LINK)
tests_t_compare_fast_LINK = $(TEST_LINK)
tests_t_cells_LINK = $(TEST_LINK)
tests_t_push_LINK = $(TEST_LINK)
tests_t_stability_LINK = $(TEST_LINK)
tests_t_facesep_LINK = $(TEST_LINK)
tests_t_refplan_LINK = $(TEST_LINK)
tests_t_plan_LINK = $(TEST_LINK)
tests_t_plansound_LINK = $(TEST_LINK)
tests_t_planbits_LINK = $(TEST_LINK)
tests_t_cellsfast_LINK = $(TEST_LINK)
tests_t_draw_LINK = $(TEST_LINK)
tests_t_request_LINK = $(TEST_LINK)
tests_t_decimals_LINK = $(TEST_LINK)
tests_t_foreignnum_LINK = $(TEST_LINK)
tests_t_cellsref_LINK = $(TEST_LINK)
tests_t_threads_LINK = $(TEST_LINK)
tests_t_quote_LINK = $(TEST_LINK)
tests_corpus_check_LINK = $(TEST_LINK)
# the former directed distance, kept as a regression check
tests_t_compare_fast_SOURCES = tests/t-compare-fast.c tests/old-hausdorff.c

SH_TESTS = \
	tests/verify-standalone.sh \
	tests/cli-batch.sh \
	tests/cli-quote.sh \
	tests/cli-draw.sh \
	tests/cli-verify.sh \
	tests/cli-plan.sh \
	tests/cert-tamper.sh \
	tests/install.sh \
	tests/cli-cone.sh \
	tests/python.sh \
	tests/cli-stability.sh \
	tests/cli-report.sh \
	tests/cli-compare.sh \
	tests/dist-files.sh \
	tests/cli-errors.sh \
	tests/cli-outfiles.sh \
	tests/cli-infiles.sh \
	tests/corpus.sh \
	tests/completion.sh \
	tests/man-examples.sh \
	tests/readme-examples.sh \
	tests/cli-text.sh \
	tests/cli-double.sh \
	tests/cdd-interop.sh \
	tests/layers.sh \
	tests/man-lint.sh \
	tests/schema.sh
# Each list longest first (CPU time in a make check): make -j starts the
# tests in this order, so the long ones start early and the short ones
# fill the end instead of a long one running alone.
TESTS += $(C_TESTS) $(SH_TESTS)
TEST_EXTENSIONS = .sh
SH_LOG_COMPILER = $(SHELL)
AM_TESTS_ENVIRONMENT = \
	WRENCHCONE='$(abs_top_builddir)/src/wrenchcone'; \
	top_srcdir='$(abs_top_srcdir)'; \
	top_builddir='$(abs_top_builddir)'; \
	CC='$(CC)'; WC_SAN='$(WC_SAN)'; MAKE='$(MAKE)'; PYTHON='$(PYTHON)'; \
	LSAN_OPTIONS="suppressions=$(abs_top_srcdir)/tests/lsan.supp:print_suppressions=0$${LSAN_OPTIONS:+:$$LSAN_OPTIONS}"; \
	export WRENCHCONE top_srcdir top_builddir CC WC_SAN MAKE PYTHON LSAN_OPTIONS;

EXTRA_DIST += $(SH_TESTS) tests/clitest.sh tests/bad tests/golden \
	tests/certs tests/lsan.supp \
	tests/update-golden.py tests/install/one-cone.c tests/cert-tamper.py \
	tests/png-pixels.py tests/stall-open.c

# The C tests' names, for running them alone (.ci/run widens them).
print-c-tests:
	@echo $(C_TESTS)
.PHONY: print-c-tests
