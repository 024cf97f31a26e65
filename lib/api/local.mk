# lib/api -- requests: a computing command from its arguments (given by
# the command line, or as a JSON request) to its answer's JSON.

lib_libwc_la_SOURCES += \
	lib/api/schema.c \
	lib/api/schemaprint.c \
	lib/api/args.c \
	lib/api/run.c \
	lib/api/runexact.c \
	lib/api/runsets.c \
	lib/api/rundocs.c \
	lib/api/request.c
wcapidir = $(pkgincludedir)/api
wcapi_HEADERS = \
	lib/api/request.h
noinst_HEADERS += \
	lib/api/schema.h \
	lib/api/args.h \
	lib/api/runners.h \
	lib/api/run.h
