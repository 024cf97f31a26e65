# lib/check -- the certificate checker: GMP arithmetic alone, sharing no
# algorithm with the solver.

lib_libwc_la_SOURCES += \
	lib/check/verify.c \
	lib/check/gmpvec.c \
	lib/check/textbuf.c \
	lib/check/motzkin.c \
	lib/check/read.c \
	lib/check/problem.c \
	lib/check/feasible.c \
	lib/check/cone.c \
	lib/check/faces.c \
	lib/check/stabread.c \
	lib/check/stabcheck.c \
	lib/check/facecheck.c
wccheckdir = $(pkgincludedir)/check
wccheck_HEADERS = \
	lib/check/verify.h
noinst_HEADERS += \
	lib/check/checker.h
