# lib/check -- the certificate checker: GMP arithmetic alone, sharing no
# algorithm with the solver.  Its own convenience library, with the lib/core
# files it uses (lib/core/local.mk), compiled without -DGMPRATIONAL and
# linked with GMP alone; lib/libwc.la includes it (Makefile.am).

lib_libwccheck_la_CPPFLAGS = -I$(top_srcdir)/lib
lib_libwccheck_la_LIBADD = $(GMP_LIBS)
lib_libwccheck_la_SOURCES += \
	lib/check/verify.c \
	lib/check/report.c \
	lib/check/gmpvec.c \
	lib/check/textbuf.c \
	lib/check/motzkin.c \
	lib/check/read.c \
	lib/check/problem.c \
	lib/check/feasible.c \
	lib/check/cone.c \
	lib/check/region.c \
	lib/check/settree.c \
	lib/check/faces.c \
	lib/check/stabread.c \
	lib/check/stabcheck.c \
	lib/check/facecheck.c \
	lib/check/setread.c \
	lib/check/setdoc.c \
	lib/check/setcheck.c \
	lib/check/plansys.c \
	lib/check/critcheck.c
wccheckdir = $(pkgincludedir)/check
wccheck_HEADERS = \
	lib/check/verify.h
noinst_HEADERS += \
	lib/check/checker.h \
	lib/check/critcheck.h \
	lib/check/faces.h \
	lib/check/feasible.h \
	lib/check/region.h \
	lib/check/setcheck.h \
	lib/check/stabcheck.h
