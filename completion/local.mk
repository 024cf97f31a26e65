# completion -- bash completion of wrenchcone.  completion/gen.sh writes
# the commands and each command's options, read from the built program's
# --help, before the functions of completion/wrenchcone.bash.in; the file
# is installed as wrenchcone in bash-completion's completionsdir (from
# pkg-config), else $(datadir)/bash-completion/completions, or where
# --with-bash-completion-dir says (configure.ac).  tests/completion.sh
# checks it.

if WC_BASH_COMPLETION
bashcompletion_DATA = completion/wrenchcone
endif
EXTRA_DIST += completion/gen.sh completion/wrenchcone.bash.in
CLEANFILES += completion/wrenchcone

completion/wrenchcone: src/wrenchcone$(EXEEXT) completion/wrenchcone.bash.in \
		completion/gen.sh
	$(AM_V_GEN)$(MKDIR_P) completion && \
	$(SHELL) $(srcdir)/completion/gen.sh src/wrenchcone$(EXEEXT) \
	  $(srcdir)/completion/wrenchcone.bash.in > $@-t && mv $@-t $@
