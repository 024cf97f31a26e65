# lib/exact -- exact polyhedral geometry: the NNC cone type, the 3-D
# kernel, the cddlib bridge, arrangements of central planes and their cells.

lib_libwc_la_SOURCES += \
	lib/exact/vec3.c \
	lib/exact/hash.c \
	lib/exact/zvec3set.c \
	lib/exact/zrow.c \
	lib/exact/cone.c \
	lib/exact/cddbridge.c \
	lib/exact/lp.c \
	lib/exact/hull3.c \
	lib/exact/fan3.c \
	lib/exact/polar3.c \
	lib/exact/cone3.c \
	lib/exact/arrangement.c \
	lib/exact/cells.c \
	lib/exact/cellrays.c \
	lib/exact/region3.c \
	lib/exact/incidence.c \
	lib/exact/box.c \
	lib/exact/set.c
wcexactdir = $(pkgincludedir)/exact
wcexact_HEADERS = \
	lib/exact/cone.h \
	lib/exact/relation.h \
	lib/exact/cells.h
noinst_HEADERS += \
	lib/exact/vec3.h \
	lib/exact/hash.h \
	lib/exact/zvec3set.h \
	lib/exact/zrow.h \
	lib/exact/cddbridge.h \
	lib/exact/lp.h \
	lib/exact/hull3.h \
	lib/exact/fan3.h \
	lib/exact/polar3.h \
	lib/exact/cone3.h \
	lib/exact/arrangement.h \
	lib/exact/incidence.h \
	lib/exact/box.h \
	lib/exact/region3.h \
	lib/exact/cddconv.inc
