# lib/core -- errors, the problem and its reader, numbers, JSON reading,
# reproducible random problems, versions, the progress hook, what a thread
# needs of its own.

# error.c, text.c, readall.c, json.c and jsontree.c are the certificate checker's
# too: they go into lib/libwccheck.la (lib/check/local.mk), which
# lib/libwc.la includes.
lib_libwccheck_la_SOURCES += \
	lib/core/error.c \
	lib/core/text.c \
	lib/core/readall.c \
	lib/core/json.c \
	lib/core/jsontree.c
lib_libwc_la_SOURCES += \
	lib/core/problem.c \
	lib/core/number.c \
	lib/core/polygon.c \
	lib/core/lexer.c \
	lib/core/parse.c \
	lib/core/rng.c \
	lib/core/qvec2.c \
	lib/core/randshape.c \
	lib/core/randdegen.c \
	lib/core/random.c \
	lib/core/version.c \
	lib/core/progress.c \
	lib/core/thread.c
wccoredir = $(pkgincludedir)/core
wccore_HEADERS = \
	lib/core/error.h \
	lib/core/limits.h \
	lib/core/problem.h \
	lib/core/random.h \
	lib/core/version.h \
	lib/core/progress.h
noinst_HEADERS += \
	lib/core/certkind.h \
	lib/core/json.h \
	lib/core/text.h \
	lib/core/readall.h \
	lib/core/polygon.h \
	lib/core/lexer.h \
	lib/core/randgen.h \
	lib/core/tick.h \
	lib/core/thread.h
