# tests -- C unit and cross-check tests, the independent references they
# compare with, and shell tests of the program.  Everything links the
# convenience library statically: no libtool wrapper between the harness
# and the program under test.

check_LTLIBRARIES += tests/libwctest.la
tests_libwctest_la_SOURCES = \
	tests/testutil.c tests/testutil.h \
	tests/ref-lp.c tests/ref-lp.h \
	tests/ref-kin.c tests/ref-kin.h \
	tests/ref-modes.c tests/ref-modes.h \
	tests/ref-stab.c tests/ref-stab.h \
	tests/ref-plan.c tests/ref-plan.h \
	tests/ref-faces.c tests/ref-faces.h \
	tests/ref-hull3.c tests/ref-hull3.h \
	tests/ref-cells.c tests/ref-cells.h

TEST_LIBS = tests/libwctest.la lib/libwc.la
C_TESTS = \
	tests/t-ref \
	tests/t-parse \
	tests/t-model \
	tests/t-cone \
	tests/t-hull3 \
	tests/t-vec3fast \
	tests/t-routes \
	tests/t-direct3 \
	tests/t-zrows3 \
	tests/t-modes \
	tests/t-modeswalk \
	tests/t-verify \
	tests/t-faces \
	tests/t-checkregion \
	tests/t-setcert \
	tests/t-random \
	tests/t-double \
	tests/t-compare \
	tests/t-compare-fast \
	tests/t-cells \
	tests/t-push \
	tests/t-stability \
	tests/t-facesep \
	tests/t-refplan \
	tests/t-plan \
	tests/t-plansound \
	tests/t-planbits \
	tests/t-cellsfast \
	tests/t-draw \
	tests/t-request \
	tests/t-decimals \
	tests/t-foreignnum
check_PROGRAMS += $(C_TESTS) tests/corpus-check
LDADD = $(TEST_LIBS)
tests_corpus_check_LDADD = lib/libwc.la
# the former directed distance, the reference of t-compare-fast
tests_t_compare_fast_SOURCES = tests/t-compare-fast.c tests/ref-hausdorff.c

SH_TESTS = \
	tests/cli-cone.sh \
	tests/cli-errors.sh \
	tests/cli-verify.sh \
	tests/cert-tamper.sh \
	tests/verify-standalone.sh \
	tests/cli-double.sh \
	tests/cli-compare.sh \
	tests/cli-stability.sh \
	tests/cli-plan.sh \
	tests/corpus.sh \
	tests/man-examples.sh \
	tests/man-lint.sh \
	tests/cdd-interop.sh \
	tests/layers.sh \
	tests/install.sh \
	tests/readme-examples.sh \
	tests/cli-draw.sh \
	tests/cli-report.sh \
	tests/dist-files.sh \
	tests/completion.sh \
	tests/cli-batch.sh \
	tests/cli-text.sh \
	tests/python.sh
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
	tests/png-pixels.py

# The C tests' names, for running them alone (.ci/run widens them).
print-c-tests:
	@echo $(C_TESTS)
.PHONY: print-c-tests
