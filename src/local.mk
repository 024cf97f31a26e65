# src -- the command-line program.  It links the convenience library
# statically, so that the tests run the real program (no libtool wrapper).

bin_PROGRAMS = src/wrenchcone
src_wrenchcone_SOURCES = src/wrenchcone.c
src_wrenchcone_LDADD = lib/libwc.la
