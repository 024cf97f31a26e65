# lib/float -- floating point, and only here: the paper's route in
# doubles, and the comparison of a foreign (floating-point) cone with the
# exact one.

lib_libwc_la_SOURCES += \
	lib/float/floatcone.c \
	lib/float/compare.c
wcfloatdir = $(pkgincludedir)/float
wcfloat_HEADERS = \
	lib/float/floatcone.h \
	lib/float/compare.h
