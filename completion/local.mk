# completion -- bash completion of wrenchcone.  completion/gen.sh writes
# the commands and each command's options, read from the built program's
# --help, before the functions of completion/wrenchcone.bash.in; the file
# completes wrenchcone-verify too, and is installed as wrenchcone and as
# wrenchcone-verify (bash-completion loads a command's completion from
# the file of its name) in bash-completion's completionsdir (from
# pkg-config), else $(datadir)/bash-completion/completions, or where
# --with-bash-completion-dir says (configure.ac).  tests/completion.sh
# checks it.

if WC_BASH_COMPLETION
bashcompletion_DATA = completion/wrenchcone completion/wrenchcone-verify
endif
EXTRA_DIST += completion/gen.sh completion/wrenchcone.bash.in
CLEANFILES += completion/wrenchcone completion/wrenchcone-verify

completion/wrenchcone: src/wrenchcone$(EXEEXT) completion/wrenchcone.bash.in \
		completion/gen.sh
	$(AM_V_GEN)$(MKDIR_P) completion && \
	$(SHELL) $(srcdir)/completion/gen.sh src/wrenchcone$(EXEEXT) \
	  $(srcdir)/completion/wrenchcone.bash.in > $@-t && mv $@-t $@

completion/wrenchcone-verify: completion/wrenchcone
	$(AM_V_GEN)cp completion/wrenchcone $@
