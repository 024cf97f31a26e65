# lib/api -- requests: a computing command from its arguments (given by
# the command line, or as a JSON request) to its answer's JSON; a batch
# of them, a line each, answered in order by one thread or several.

lib_libwc_la_SOURCES += \
	lib/api/run.c \
	lib/api/request.c \
	lib/api/batch.c
wcapidir = $(pkgincludedir)/api
wcapi_HEADERS = \
	lib/api/request.h \
	lib/api/batch.h
noinst_HEADERS += \
	lib/api/run.h
