# man -- the manual pages.  The pages of the source tree name the example
# problems as data/NAME and run from the top of the tree (man ./man/PAGE;
# tests/man-examples.sh runs their EXAMPLES there).  The installed pages,
# man/installed/PAGE, are made from them: data/ becomes $(pkgdatadir)/,
# where data/local.mk installs the files, the lines between '.\" source {'
# and '.\" }' go, and the lines '.\"I TEXT' become TEXT.  tests/install.sh
# runs the installed pages' examples with the installed program.

WC_MAN_SRC = man/wrenchcone.1 man/wrenchcone-verify.1 man/wrenchcone.5 \
	man/wrenchcone-certificate.5
EXTRA_DIST += $(WC_MAN_SRC)
man_MANS = man/installed/wrenchcone.1 man/installed/wrenchcone-verify.1 \
	man/installed/wrenchcone.5 man/installed/wrenchcone-certificate.5
CLEANFILES += $(man_MANS)

# $(pkgdatadir) as a sed replacement that prints as roff: \ & | escaped
# for sed, then - written \-.
wc_man_edit = d=$$(printf '%s\n' '$(pkgdatadir)' | sed -e 's/[\\&|]/\\&/g' -e 's/-/\\\\-/g') && \
	$(MKDIR_P) man/installed && \
	sed -e '/^\.\\" source {$$/,/^\.\\" }$$/d' -e 's/^\.\\"I //' \
	    -e "s|^data/|$$d/|" -e "s|\([^A-Za-z0-9_./-]\)data/|\1$$d/|g"

man/installed/wrenchcone.1: man/wrenchcone.1 Makefile
	$(AM_V_GEN)$(wc_man_edit) $(srcdir)/man/wrenchcone.1 > $@-t && mv $@-t $@
man/installed/wrenchcone-verify.1: man/wrenchcone-verify.1 Makefile
	$(AM_V_GEN)$(wc_man_edit) $(srcdir)/man/wrenchcone-verify.1 > $@-t && mv $@-t $@
man/installed/wrenchcone.5: man/wrenchcone.5 Makefile
	$(AM_V_GEN)$(wc_man_edit) $(srcdir)/man/wrenchcone.5 > $@-t && mv $@-t $@
man/installed/wrenchcone-certificate.5: man/wrenchcone-certificate.5 Makefile
	$(AM_V_GEN)$(wc_man_edit) $(srcdir)/man/wrenchcone-certificate.5 > $@-t && mv $@-t $@
