# lib/io -- the printers: every result as text, JSON or cdd.

lib_libwc_la_SOURCES += \
	lib/io/printutil.c \
	lib/io/print.c \
	lib/io/stabprint.c \
	lib/io/planprint.c
wciodir = $(pkgincludedir)/io
wcio_HEADERS = \
	lib/io/print.h
noinst_HEADERS += \
	lib/io/printutil.h
