# lib/draw -- figures: scenes of floating-point primitives built from
# exact results, and their SVG writer.  Floating point is allowed here,
# only in drawings.

lib_libwc_la_SOURCES += \
	lib/draw/scene.c \
	lib/draw/svg.c \
	lib/draw/part.c \
	lib/draw/figmode.c \
	lib/draw/figsets.c \
	lib/draw/figgraph.c \
	lib/draw/report.c
noinst_HEADERS += \
	lib/draw/scene.h \
	lib/draw/figure.h
