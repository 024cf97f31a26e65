# lib/api -- requests: a computing command from its arguments (given by
# the command line, or as a JSON request) to its answer's JSON; a batch
# of them, a line each, answered in order by one thread or several.

lib_libwc_la_SOURCES += \
	lib/api/schema.c \
	lib/api/schemaprint.c \
	lib/api/args.c \
	lib/api/run.c \
	lib/api/runexact.c \
	lib/api/runsets.c \
	lib/api/rundocs.c \
	lib/api/request.c \
	lib/api/batch.c
wcapidir = $(pkgincludedir)/api
wcapi_HEADERS = \
	lib/api/request.h \
	lib/api/batch.h
noinst_HEADERS += \
	lib/api/schema.h \
	lib/api/args.h \
	lib/api/runners.h \
	lib/api/run.h
