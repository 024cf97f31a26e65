# python -- the Python module wrenchcone: pure Python over the shared
# library through ctypes (python/wrenchcone/__init__.py; doc/python.md).
# From the tree it runs as is (PYTHONPATH=python) and finds the library
# it was built with.  make install puts it in $(pythondir)/wrenchcone,
# the line "_INSTALLED_LIBDIR = None" replaced by the installed
# library's directory, as the installed manual pages name $(pkgdatadir)
# (man/local.mk).  Without a Python 3 at configure time (AM_PATH_PYTHON)
# nothing is installed and tests/python.sh, which runs the pytest suite
# of python/tests, SKIPs.

WC_PYTHON_TESTS = python/tests/conftest.py python/tests/test_exact.py \
	python/tests/test_errors.py python/tests/test_roundtrip.py \
	python/tests/test_float_regression.py \
	python/tests/test_text.py
EXTRA_DIST += python/wrenchcone/__init__.py $(WC_PYTHON_TESTS)

if WC_PYTHON
wcpythondir = $(pythondir)/wrenchcone
nodist_wcpython_PYTHON = python/installed/wrenchcone/__init__.py
CLEANFILES += python/installed/wrenchcone/__init__.py

# $(libdir) as a Python string literal (\ and ' escaped), then as a sed
# replacement (\ & | escaped).
python/installed/wrenchcone/__init__.py: python/wrenchcone/__init__.py Makefile
	$(AM_V_GEN)d=$$(printf '%s\n' '$(libdir)' | sed -e 's/[\\'\'']/\\&/g' \
	    -e 's/[\\&|]/\\&/g') && \
	$(MKDIR_P) python/installed/wrenchcone && \
	sed -e "s|^_INSTALLED_LIBDIR = None\$$|_INSTALLED_LIBDIR = '$$d'|" \
	    $(srcdir)/python/wrenchcone/__init__.py > $@-t && \
	grep -q "^_INSTALLED_LIBDIR = '" $@-t && mv $@-t $@
endif
