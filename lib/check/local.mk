# lib/check -- the certificate checker: GMP arithmetic alone, sharing no
# algorithm with the solver.

lib_libwc_la_SOURCES += \
	lib/check/verify.c
wccheckdir = $(pkgincludedir)/check
wccheck_HEADERS = \
	lib/check/verify.h
