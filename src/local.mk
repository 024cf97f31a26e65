# src -- the command-line program: a thin shell over the library's
# requests (cli-request.c), the few commands with rules of their own
# (cmd-*.c), what they share (cli*.c), and main with the command table
# (wrenchcone.c).  It
# links the convenience library statically, so that the tests run the real
# program (no libtool wrapper).

bin_PROGRAMS = src/wrenchcone
src_wrenchcone_SOURCES = src/wrenchcone.c src/commands.h \
	src/cli.c src/cli-base.c src/cli-options.c src/cli-memory.c \
	src/cli-progress.c src/cli-output.c src/cli-file.c src/cli.h src/cli-base.h \
	src/cmd-cone.c src/cmd-compare.c src/cmd-batch.c src/cli-request.c
src_wrenchcone_LDADD = lib/libwc.la

# The standalone certificate checker: the check library and GMP, nothing
# else (no -DGMPRATIONAL, no FLINT, no cddlib), so that a FLINT or cddlib
# call in the checker cannot link (tests/verify-standalone.sh).
bin_PROGRAMS += src/wrenchcone-verify
src_wrenchcone_verify_SOURCES = src/wrenchcone-verify.c src/cli-base.c \
	src/cli-base.h
src_wrenchcone_verify_CPPFLAGS = -I$(top_srcdir)/lib
src_wrenchcone_verify_LDADD = lib/libwccheck.la $(GMP_LIBS)
