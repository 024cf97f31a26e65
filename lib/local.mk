# lib/local.mk -- the installed library and its umbrella header.

lib_LTLIBRARIES = lib/libwrenchcone.la
lib_libwrenchcone_la_SOURCES =
# A C source file nobody writes, so that libtool links with the C compiler.
nodist_EXTRA_lib_libwrenchcone_la_SOURCES = lib/dummy.c
lib_libwrenchcone_la_LIBADD = lib/libwc.la
lib_libwrenchcone_la_LDFLAGS = -version-info 0:0:0 -no-undefined \
	-export-symbols-regex '^wc_'

pkginclude_HEADERS = lib/wrenchcone.h
pkgconfig_DATA = lib/wrenchcone.pc
