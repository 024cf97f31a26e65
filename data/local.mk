# data -- the example problems of the README and the manual pages, and the
# corpus of problems with the exact cone of every mode (data/corpus/README).
# make install puts them in $(pkgdatadir) (the problems) and
# $(pkgdatadir)/corpus, without the data/ prefix; the installed manual
# pages name them there (man/local.mk).  tests/data-lists.sh checks that
# these lists name every file of data/.

dist_pkgdata_DATA = \
	data/disk-two-fixels-insert.wc \
	data/disk-two-fixels.wc \
	data/peg-in-hole.wc \
	data/section4.wc \
	data/three-fixels-insert.wc \
	data/three-fixels.wc

corpusdir = $(pkgdatadir)/corpus
dist_corpus_DATA = \
	data/corpus/README \
	data/corpus/r1-s2-degenerate-disk.cones.json \
	data/corpus/r1-s2-degenerate-disk.wc \
	data/corpus/r1-s3.cones.json \
	data/corpus/r1-s3.wc \
	data/corpus/r2-s1-degenerate-polygon.cones.json \
	data/corpus/r2-s1-degenerate-polygon.wc \
	data/corpus/r2-s1-disk.cones.json \
	data/corpus/r2-s1-disk.wc \
	data/corpus/r2-s2-degenerate.cones.json \
	data/corpus/r2-s2-degenerate.wc \
	data/corpus/r2-s4-f1_2-1_5.cones.json \
	data/corpus/r2-s4-f1_2-1_5.wc \
	data/corpus/r3-s1-degenerate-disk.cones.json \
	data/corpus/r3-s1-degenerate-disk.wc \
	data/corpus/r3-s11-f0.cones.json \
	data/corpus/r3-s11-f0.wc \
	data/corpus/r3-s7-degenerate.cones.json \
	data/corpus/r3-s7-degenerate.wc \
	data/corpus/r3-s8-polygon.cones.json \
	data/corpus/r3-s8-polygon.wc \
	data/corpus/r4-s7-degenerate.cones.json \
	data/corpus/r4-s7-degenerate.wc \
	data/corpus/r4-s8-degenerate-polygon.cones.json \
	data/corpus/r4-s8-degenerate-polygon.wc
