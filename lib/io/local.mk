# lib/io -- the printers: every result as text, JSON or cdd.

lib_libwc_la_SOURCES += \
	lib/io/printutil.c \
	lib/io/print.c \
	lib/io/cddwrite.c \
	lib/io/stabprint.c \
	lib/io/certprint.c \
	lib/io/stabcertprint.c \
	lib/io/plancertprint.c \
	lib/io/planprint.c \
	lib/io/sweepprint.c \
	lib/io/answerprint.c \
	lib/io/fconeprint.c \
	lib/io/compareprint.c
wciodir = $(pkgincludedir)/io
wcio_HEADERS = \
	lib/io/print.h \
	lib/io/fconeprint.h \
	lib/io/compareprint.h
noinst_HEADERS += \
	lib/io/printutil.h \
	lib/io/cddwrite.h \
	lib/io/certprint.h \
	lib/io/answerprint.h
