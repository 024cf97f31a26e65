# lib/model -- the contact model: J, M, friction edges, mode letters,
# the paper's Table 2.

lib_libwc_la_SOURCES += \
	lib/model/model.c \
	lib/model/mode.c
wcmodeldir = $(pkgincludedir)/model
wcmodel_HEADERS = \
	lib/model/model.h \
	lib/model/mode.h
noinst_HEADERS += \
	lib/model/table2.h
