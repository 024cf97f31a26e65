# lib/float -- floating point, and only here: the paper's route in
# doubles, and the comparison of a foreign (floating-point) cone with the
# exact one.

lib_libwc_la_SOURCES += \
	lib/float/dmat.c \
	lib/float/floatcone.c \
	lib/float/fconediff.c \
	lib/float/angle.c \
	lib/float/hausdorff.c \
	lib/float/foreign.c \
	lib/float/foreigncdd.c \
	lib/float/compare.c
wcfloatdir = $(pkgincludedir)/float
wcfloat_HEADERS = \
	lib/float/floatcone.h \
	lib/float/compare.h
noinst_HEADERS += \
	lib/float/dmat.h \
	lib/float/angle.h \
	lib/float/foreign.h
