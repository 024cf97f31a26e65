# src -- the command-line program: one file per command (cmd-*.c), what
# they share (cli*.c), and main with the command table (wrenchcone.c).  It
# links the convenience library statically, so that the tests run the real
# program (no libtool wrapper).

bin_PROGRAMS = src/wrenchcone
src_wrenchcone_SOURCES = src/wrenchcone.c src/commands.h \
	src/cli.c src/cli-options.c src/cli-memory.c \
	src/cli-progress.c src/cli.h \
	src/cmd-cone.c src/cmd-modes.c src/cmd-feasible.c src/cmd-verify.c \
	src/cmd-random.c src/cmd-compare.c src/cmd-classify.c \
	src/cmd-stability.c src/cmd-plan.c src/cmd-sweep.c
src_wrenchcone_LDADD = lib/libwc.la
