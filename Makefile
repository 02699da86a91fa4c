# Makefile of the adaptive Verlet integrators (avi).
#
#   make          tangle, build, every figure, the woven PDF in two volumes
#                 (doc/avi.pdf, doc/avi-vol2.pdf) and its web edition
#                 (doc/html/avi.html)
#   make check    unit tests, golden files, chunk check, the web edition in a
#                 browser; ends "N passed, N failed"
#   make record   re-record the golden files from figures/data (commit separately)
#   make deps     install the Debian packages that make and make check need
#                 (make installs its own, make check the rest)
#   make clean    remove everything generated
#
# Only src/*.nw is hand-written C, headers and gnuplot; tangle/ is generated.

SHELL := /bin/bash
.SHELLFLAGS := -eo pipefail -c
.DELETE_ON_ERROR:
.SUFFIXES:

# Every core, unless the command line says how many jobs (make -j1 runs one
# at a time): the targets are independent where make sees them so, and the
# benchmarks time their runs one after another inside one recipe.
NPROC := $(shell nproc 2>/dev/null || echo 1)
ifeq ($(filter -j%,$(MAKEFLAGS)),)
MAKEFLAGS += -j$(NPROC)
endif

NW      := $(sort $(wildcard src/*.nw))
CC      ?= cc
CFLAGS  := -std=c11 -O2 -g -Wall -Wextra -Wpedantic -Werror -ffp-contract=off \
           -D_POSIX_C_SOURCE=200809L
LDLIBS  := -lgsl -lgslcblas -lm
B       := build

# make check SANITIZE=1: everything built with the address and UB sanitizers,
# in its own build folder so that the two builds never mix.
ifeq ($(SANITIZE),1)
CFLAGS  += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
LDFLAGS += -fsanitize=address,undefined
B       := build-san
endif

.PHONY: all figures doc html check record deps clean bench bench-python bench-split install install-doc uninstall memcheck cli python
# The stamp of the book's packages comes first, so that their installation
# starts as soon as the compilers are in and runs beside the build (below).
all: $(B)/.deps-book figures doc html cli

# --- dependencies ---------------------------------------------------------
# Debian 12 packages, the compilers included (a minimal Debian has neither cc
# nor c++), in three lists.  DEB_PKGS is what make's first steps use: gcc
# and libc6-dev build the library, the programs and the figures' data,
# noweb tangles and weaves, gnuplot (with fonts-lmodern for its lettering)
# draws the figures.  DEB_BOOK_PKGS is what make uses after those: TeX Live
# typesets both volumes, TeX4ht (texlive-plain-generic, make4ht in
# texlive-extra-utils) the web edition, and the Python package that make
# builds imports NumPy (python3-numpy) and runs its ensembles on Dask
# (python3-distributed).  Those are most of the download and of apt's time
# (about 50 of 60 seconds on a fresh Debian), and only the book and the
# Python package wait for their stamp: they install while the library is
# compiled and the figures' programs run.  DEB_CHECK_PKGS is what only make
# check uses, installed when make check first runs: libcmocka-dev for the
# unit tests (no test is built by make), numdiff for the golden files, g++
# and pkg-config for the check of the installed library and headers,
# groff-base for the man page's test, strace to widen a race in the
# program's test, chromium-headless-shell to read the
# web edition, poppler-utils (pdftotext) and python3 to read the built
# PDFs, python3-pytest for the Python package's tests.  make deps installs
# all three lists.  Installed with apt-get as root, with sudo otherwise
# (one apt-get at a time: each stamp waits for the one before); a user
# with neither gets the command to run and exit 2.
DEB_PKGS := gcc libc6-dev noweb libgsl-dev gnuplot-nox fonts-lmodern
DEB_PY_PKGS := python3 python3-numpy python3-distributed
DEB_BOOK_PKGS := texlive-latex-base texlive-latex-recommended texlive-fonts-recommended \
            texlive-plain-generic texlive-extra-utils python3-matplotlib python3-cairo
DEB_CHECK_PKGS := libcmocka-dev numdiff g++ pkg-config groff-base strace \
            chromium-headless-shell poppler-utils python3 python3-pytest
# $(call APT_INSTALL,packages): install those of the packages that are missing.
APT_INSTALL = missing=$$(for p in $(1); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' \
	    || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  missing=$$(echo $$missing); \
	  if [ "$$(id -u)" = 0 ]; then sudo=; \
	  elif command -v sudo > /dev/null; then sudo=sudo; \
	  else echo "make: missing Debian packages; as root, run: apt-get install --no-install-recommends $$missing" >&2; \
	    exit 2; fi; \
	  echo "make: installing missing Debian packages: $$missing"; \
	  $$sudo apt-get update -q; \
	  DEBIAN_FRONTEND=noninteractive $$sudo apt-get install -y -q \
	    --no-install-recommends $$missing; \
	fi
$(B)/.deps:
	@$(call APT_INSTALL,$(DEB_PKGS))
	@mkdir -p $(B) && touch $@
$(B)/.deps-python: | $(B)/.deps
	@$(call APT_INSTALL,$(DEB_PY_PKGS))
	@mkdir -p $(B) && touch $@
$(B)/.deps-book: | $(B)/.deps-python
	@$(call APT_INSTALL,$(DEB_BOOK_PKGS))
	@mkdir -p $(B) && touch $@
$(B)/.deps-check: | $(B)/.deps-book
	@$(call APT_INSTALL,$(DEB_CHECK_PKGS))
	@mkdir -p $(B) && touch $@
deps:
	@$(call APT_INSTALL,$(DEB_PKGS) $(DEB_PY_PKGS) $(DEB_BOOK_PKGS) $(DEB_CHECK_PKGS))
	@mkdir -p $(B) && touch $(B)/.deps $(B)/.deps-python $(B)/.deps-book $(B)/.deps-check

# --- tangling ---------------------------------------------------------------
# Every root chunk (found by noroots, never listed by hand) is tangled to
# tangle/<root>, on every core (xargs -P); .c files with #line directives
# (-L) so that compiler errors and debuggers point into src/*.nw.  cpif
# rewrites a file only when its text changed, so make rebuilds only what
# depends on a changed chunk.  (The stale
# test reads the roots from a here-string: `echo | grep -q` under pipefail can
# fail when grep exits early and echo gets SIGPIPE.)  The list of
# roots becomes tangle/files.mk, which make reads back (and re-reads after
# tangling).  Files of roots that no longer exist are removed.
tangle/files.mk: $(NW) | $(B)/.deps
	@roots=$$(noroots $(NW) | sed -e 's/^<<//' -e 's/>>$$//'); \
	printf '%s\n' $$roots | xargs -P $(NPROC) -n 16 sh -c 'for r; do \
	  mkdir -p "tangle/$${r%/*}"; case $$r in *.c) L=-L;; *) L=;; esac; \
	  notangle $$L -R"$$r" $(NW) > "tangle/.tmp.$$$$" \
	    && cpif "tangle/$$r" < "tangle/.tmp.$$$$" || exit 255; \
	done; rm -f "tangle/.tmp.$$$$"' sh; \
	for f in $$(cd tangle && find lib ref figkit fig test golden bench examples cli weave python -type f 2>/dev/null); do \
	  grep -qxF "$$f" <<< "$$roots" || { echo "removing stale tangle/$$f"; rm -f tangle/$$f; }; \
	done; \
	{ echo "ROOTS := $$(echo $$roots)"; \
	  for kind in lib ref figkit fig test bench cli; do \
	    echo "$${kind^^}_C := $$(echo "$$roots" | grep "^$$kind/.*\.c$$" | sed 's|^|tangle/|' | tr '\n' ' ')"; done; \
	  echo "GP := $$(echo "$$roots" | grep '^fig/.*\.gp$$' | sed 's|^|tangle/|' | tr '\n' ' ')"; \
	} > $@
	@echo "tangled $$(noroots $(NW) | wc -l) root chunks from $(words $(NW)) files"

ifeq ($(filter clean,$(MAKECMDGOALS)),)
include tangle/files.mk
endif

# The cost guard's pinned counts, which its section quotes (src/95-bench.nw).
doc/gen/cost-guard.summary: tangle/bench/cost-pins.awk tangle/test/test-cost-guard.c
	@mkdir -p doc/gen
	awk -f $^ > $@

# --- building ---------------------------------------------------------------
# GCC's quadmath.h lives in GCC's own header directory, which Clang does not
# search; -idirafter adds it after every other, so that Clang takes only
# quadmath.h from there (for GCC it is a directory it already searches).
GCC_INC  := $(shell gcc -print-file-name=include 2>/dev/null)
INC      := -Itangle/lib -Itangle/ref -Itangle/figkit $(if $(GCC_INC),-idirafter $(GCC_INC))
LIB_O    := $(patsubst tangle/%.c,$(B)/%.o,$(LIB_C))
FIGKIT_O := $(patsubst tangle/%.c,$(B)/%.o,$(FIGKIT_C))
FIGS     := $(patsubst tangle/fig/%.gp,%,$(GP))
FIG_BIN  := $(patsubst tangle/fig/%.c,$(B)/fig/%,$(FIG_C))
TEST_BIN := $(patsubst tangle/test/%.c,$(B)/test/%,$(TEST_C))
BENCH_BIN := $(patsubst tangle/bench/%.c,$(B)/bench/%,$(filter-out tangle/bench/kit.c,$(BENCH_C)))
CLI_O    := $(patsubst tangle/%.c,$(B)/%.o,$(CLI_C))
CLI_BIN  := $(B)/cli/avi

$(B)/%.o: tangle/%.c | $(B)/.deps
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(INC) -MMD -MP -c $< -o $@

$(B)/libavi.a: $(LIB_O)
	rm -f $@ && ar rcs $@ $^

# The shared library is built from position-independent objects of its own.
PIC_O := $(patsubst tangle/%.c,$(B)/pic/%.o,$(LIB_C))
$(B)/pic/%.o: tangle/%.c | $(B)/.deps
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -fPIC $(INC) -MMD -MP -c $< -o $@
$(B)/libavi.so: $(PIC_O)
	$(CC) -shared -Wl,-soname,libavi.so.0 $(LDFLAGS) $^ $(LDLIBS) -o $@

$(FIG_BIN): $(B)/fig/%: $(B)/fig/%.o $(FIGKIT_O) $(B)/libavi.a
	$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@

# rf-fig1 computes its grid of runs on all cores with OpenMP, hier-triple its
# references and its rotated starts.
$(B)/fig/rf-fig1.o: CFLAGS += -fopenmp
$(B)/fig/rf-fig1: LDFLAGS += -fopenmp
$(B)/fig/hier-triple.o: CFLAGS += -fopenmp
$(B)/fig/hier-triple: LDFLAGS += -fopenmp
$(B)/bench/bench-steps: LDFLAGS += -pthread
$(B)/bench/bench-kepler-wp.o: CFLAGS += -fopenmp
$(B)/bench/bench-kepler-wp: LDFLAGS += -fopenmp
$(B)/bench/bench-kepler-long.o: CFLAGS += -fopenmp
$(B)/bench/bench-kepler-long: LDFLAGS += -fopenmp
$(B)/bench/bench-cubic-wp.o: CFLAGS += -fopenmp
$(B)/bench/bench-cubic-wp: LDFLAGS += -fopenmp
$(B)/bench/bench-cubic-wp: $(FIGKIT_O)
$(B)/bench/bench-threebody-wp.o: CFLAGS += -fopenmp
$(B)/bench/bench-threebody-wp: LDFLAGS += -fopenmp
$(B)/bench/bench-atlas.o: CFLAGS += -fopenmp
$(B)/bench/bench-atlas: LDFLAGS += -fopenmp
$(B)/bench/bench-atlas: $(FIGKIT_O)
# bench-targets starts the hierarchical triple from the figure kit's start
$(B)/bench/bench-targets: $(FIGKIT_O)
# and bench-split the planet with a companion
$(B)/bench/bench-split: $(FIGKIT_O)

# The reference solutions in binary128 (src/94-references.nw): an archive of
# their own, not part of libavi, linked with GCC's libquadmath (Debian:
# libgcc-12-dev, which gcc depends on) only into the programs that use them.
REF_O    := $(patsubst tangle/%.c,$(B)/%.o,$(REF_C))
QUAD_BIN := $(B)/test/test-ref $(B)/test/test-after $(B)/test/test-gbs $(B)/bench/bench-kepler-wp $(B)/bench/bench-logh \
            $(B)/bench/bench-threebody-wp $(B)/bench/bench-targets $(B)/bench/bench-split $(B)/fig/outer-solar \
            $(B)/fig/burrau $(B)/fig/hier-triple $(B)/test/test-kepler-split
$(B)/libavi-ref.a: $(REF_O)
	rm -f $@ && ar rcs $@ $^
$(QUAD_BIN): $(B)/libavi-ref.a
# test-gbs runs GSL's rk8pd through the figure kit's harness too
$(B)/test/test-gbs: $(FIGKIT_O)
$(QUAD_BIN): LDLIBS += -lquadmath

# the first program of Chapter 1 (src/10-intro.nw), against the build tree
EXAMPLE_BIN := $(B)/examples/henon-heiles
$(EXAMPLE_BIN): $(B)/examples/%: tangle/examples/%.c $(B)/libavi.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(INC) $(LDFLAGS) $< $(B)/libavi.a $(LDLIBS) -o $@
all: $(EXAMPLE_BIN)

# the Python package avi (src/95a-python.nw): its modules and a link to the
# shared library in build/python/avi, where PYTHONPATH=build/python finds
# them; python/layout prints C's layout of the structures for its test
PYTHON  ?= /usr/bin/python3
PY_SRC  := $(filter tangle/python/avi/%.py,$(ROOTS:%=tangle/%))
PY_PKG  := $(patsubst tangle/%,$(B)/%,$(PY_SRC)) $(B)/python/avi/libavi.so.0 \
	   $(B)/python/layout
python: $(PY_PKG)
all: python
$(PY_PKG): | $(B)/.deps-python
$(B)/python/avi/%.py: tangle/python/avi/%.py
	@mkdir -p $(@D)
	cp $< $@
$(B)/python/avi/libavi.so.0: $(B)/libavi.so
	@mkdir -p $(@D)
	ln -sf ../../libavi.so $@
# the figure of Result.plot in Part IV, drawn by the package with matplotlib
PY_FIG := figures/py-plot
$(PY_FIG).pdf $(PY_FIG).png &: $(PY_PKG) tangle/python/examples/plot.py | $(B)/.deps-book
	@mkdir -p figures
	cd $(B)/python && PYTHONPATH=. $(PYTHON) ../../tangle/python/examples/plot.py ../../$(PY_FIG)
figures: $(PY_FIG).pdf $(PY_FIG).png
$(B)/python/layout: tangle/python/layout.c tangle/lib/avi.h
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(INC) $< -o $@

# the command-line program avi (src/99b-cli.nw), linked from all files of
# cli/; its fuzz test links them all but main.c
cli: $(CLI_BIN)
$(CLI_BIN): $(CLI_O) $(B)/libavi.a
	$(CC) $(CFLAGS) $(LDFLAGS) $^ $(LDLIBS) -o $@
$(B)/test/test-cli-fuzz: $(filter-out %/main.o,$(CLI_O))

# the unit tests, built by make check only, need cmocka (DEB_CHECK_PKGS)
$(TEST_BIN:%=%.o): | $(B)/.deps-check
$(TEST_BIN): $(B)/test/%: $(B)/test/%.o $(B)/libavi.a
	$(CC) $(CFLAGS) $(LDFLAGS) $(filter %.o %/libavi-ref.a,$^) $(B)/libavi.a -lcmocka $(LDLIBS) -o $@

# bench/kit.c is no program: the benchmarks' kit, linked into every one
$(BENCH_BIN): $(B)/bench/%: $(B)/bench/%.o $(B)/bench/kit.o $(B)/libavi.a
	$(CC) $(CFLAGS) $(LDFLAGS) $(filter %.o %/libavi-ref.a,$^) $(B)/libavi.a $(LDLIBS) -o $@

# The compiler's lists of headers, one per object, at every depth the
# objects have (the library's rooms are two deep: build/lib/schemes/).
-include $(wildcard $(B)/*/*.d $(B)/*/*/*.d $(B)/pic/*/*.d $(B)/pic/*/*/*.d)

# --- figures ----------------------------------------------------------------
# A figure program fig/<id>.c writes figures/data/<id>*.tsv and, last, the
# summary figures/data/<id>.summary; the gnuplot script fig/<id>.gp draws
# figures/<id>.pdf and figures/<id>.png from them.
figures: $(FIGS:%=figures/%.pdf) $(FIGS:%=figures/%.png)

figures/data/%.summary: $(B)/fig/%
	@mkdir -p figures/data
	$< --out figures/data

figures/%.pdf figures/%.png: tangle/fig/%.gp figures/data/%.summary
	gnuplot -e "datadir='figures/data'; outdir='figures'" $<

# HL Fig. 5 draws its panel (c) from the data of hl-fig5c.
figures/hl-fig5.pdf figures/hl-fig5.png: figures/data/hl-fig5c.summary

# --- the woven document -----------------------------------------------------
# All chapters are woven in one scope, so chunk cross-references and the
# identifier index span the whole book; doc/avi.tex and doc/avi-vol2.tex are
# the hand-written masters of its two volumes, doc/preamble.tex their preamble.
doc: doc/avi.pdf doc/avi-vol2.pdf

doc/gen/woven.tex: $(NW) tangle/weave/c-index.awk tangle/weave/escape-names.awk | $(B)/.deps
	@mkdir -p doc/gen
	noweave -n -filter 'awk -v kind=defn -f tangle/weave/c-index.awk' -index \
	  -filter 'awk -v kind=use -f tangle/weave/c-index.awk' $(NW) \
	  > doc/gen/.tmp 2> doc/gen/.err || { cat doc/gen/.err; false; }
	@! test -s doc/gen/.err || { cat doc/gen/.err; echo "noweave: a stage failed"; false; }
	awk -f tangle/weave/escape-names.awk doc/gen/.tmp | cpif $@ && rm -f doc/gen/.tmp

# Numbers quoted in the text come from the figures' summaries: each line
# "key value" of figures/data/<id>.summary becomes \val{<id>}{key} (three
# significant digits) and \valfull{<id>}{key} (six), exponents as powers of 10
# below 1e-3 ({10}^{e}: one number 10 with its exponent, in the web edition too).
doc/gen/values.tex: $(FIGS:%=figures/data/%.summary) doc/gen/bench-steps.summary \
	  doc/gen/bench-kepler-wp.summary doc/gen/bench-threebody-wp.summary \
	  doc/gen/bench-kepler-long.summary doc/gen/bench-pendulum.summary \
	  doc/gen/bench-cubic-wp.summary doc/gen/bench-atlas.summary doc/gen/bench-pairs.summary \
	  doc/gen/bench-targets.summary doc/gen/bench-logh.summary doc/gen/cost-guard.summary \
  doc/gen/python-speed.summary doc/gen/burrau-ensemble.summary doc/gen/bench-split.summary
	@mkdir -p doc/gen
	awk 'function fmt(v, d,  s, m, e) { \
	       if (v == int(v) && v < 1e15 && v > -1e15) return sprintf("%d", v); \
	       s = sprintf("%." d "g", v); \
	       if (v != 0 && v < 1e-3 && v > -1e-3) s = sprintf("%." (d - 1) "e", v); \
	       if (s !~ /e/) return s; \
	       split(s, m, "e"); e = m[2] + 0; \
	       return "\\ensuremath{" m[1] "\\times{10}^{" e "}}" } \
	     FNR == 1 { id = FILENAME; sub(/.*\//, "", id); sub(/\.summary$$/, "", id) } \
	     NF == 2 { printf "\\expandafter\\def\\csname val:%s:%s\\endcsname{%s}\n", id, $$1, fmt($$2, 3); \
	               printf "\\expandafter\\def\\csname valfull:%s:%s\\endcsname{%s}\n", id, $$1, fmt($$2, 6) }' \
	  $^ > $@

# The concordance of the papers' equations (src/95b-concordance.nw), from the
# sources and, for the chunks' numbers, the woven index.
doc/gen/concordance.tex: tangle/weave/concordance.awk doc/gen/woven-ix.tex $(NW)
	@mkdir -p doc/gen
	awk -f $^ > $@

# The woven text is cut into the PDF's two volumes at the files' boundaries
# (noweave marks each with \nwfilename): Volume II is VOL2_NW, the unit tests
# and the program; the index data that noweave writes after the last file
# goes to both (doc/preamble.tex says how the volumes refer to each other).
VOL2_NW := src/99a-tests.nw src/99b-cli.nw src/99c-python-tests.nw
WOVEN   := doc/gen/woven-1.tex doc/gen/woven-2.tex doc/gen/woven-ix.tex
$(WOVEN) &: doc/gen/woven.tex
	awk -v vol2=' $(VOL2_NW) ' -v v1=doc/gen/woven-1.tex -v v2=doc/gen/woven-2.tex \
	  -v ix=doc/gen/woven-ix.tex \
	  'BEGIN { out = v1 } \
	   /^\\nwixlogsorted/ { print > ix; next } \
	   { line = $$0; \
	     while ((i = index(line, "\\nwfilename{")) > 0) { \
	       printf "%s", substr(line, 1, i - 1) > out; \
	       f = substr(line, i + 12); f = substr(f, 1, index(f, "}") - 1); \
	       out = index(vol2, " " f " ") ? v2 : v1; \
	       printf "%s", substr(line, i, 12) > out; line = substr(line, i + 12) } \
	     print line > out }' $<

# Each volume reads what the other's .aux says of its pages, chunks and
# identifiers (doc/gen/<master>.ext, and doc/gen/<master>.xr.aux, a copy of
# its .aux for xr-hyper).  The two are typeset as one fixed point, in
# rounds: in each round Volume I gets one pdflatex pass, reading its own
# .aux, .toc and .out and Volume II's .ext of the round before, and then
# Volume II one pass, reading its own files and the .ext Volume I has just
# written, where Volume I says on which page it ends and so where Volume II
# starts.  The rounds stop at the first that changes none of these files
# (at most ten).  Typeset one after the other, the volumes settle in three
# rounds from a clean doc/gen: side by side, each reading the other's
# files of the round before, Volume II learned Volume I's length a round
# late and its page numbers (on which Volume I's references to it depend)
# a round after that: five rounds, ten passes against six, whose CPU time
# the web edition, typeset beside them, was waiting for.  Not latexmk,
# which settles one file at a time: run per volume inside the rounds, it
# ended each with a pass that only confirmed what the next round typeset
# again.  The build fails on an undefined reference, a link to nowhere or
# an overfull box over 10pt in either.
DOC_DEPS = doc/avi.tex doc/avi-vol2.tex doc/preamble.tex doc/indexes.tex doc/bibliography.tex $(WOVEN) \
	   doc/gen/values.tex $(FIGS:%=figures/%.pdf) $(PY_FIG).pdf doc/gen/bench.stamp doc/gen/concordance.tex
PDFLATEX = pdflatex -interaction=nonstopmode -halt-on-error -output-directory=gen
DOC_STATE = gen/avi.aux gen/avi.toc gen/avi.out gen/avi.ext \
	    gen/avi-vol2.aux gen/avi-vol2.toc gen/avi-vol2.out gen/avi-vol2.ext
doc/avi.pdf doc/avi-vol2.pdf &: $(DOC_DEPS) | $(B)/.deps-book
	cd doc && touch gen/avi.ext gen/avi-vol2.ext && for round in 1 2 3 4 5 6 7 8 9 10 0; do \
	  test $$round != 0 || { echo "doc: the two volumes did not settle in ten rounds"; exit 1; }; \
	  before=$$(cat $(DOC_STATE) 2> /dev/null | md5sum || :); \
	  for v in avi avi-vol2; do \
	    $(PDFLATEX) $$v.tex > gen/pdflatex-$$v.out 2>&1 || { tail -40 gen/pdflatex-$$v.out; exit 1; }; \
	    sed -n -e 's/^\\newsublabel{/\\avi@xsublabel{/p' -e '/^\\nwixadd{/p' \
	      -e '/^\\gdef\\avivolone/p' -e 's/^\\newlabel/% &/p' gen/$$v.aux > gen/$$v.ext; \
	    cp gen/$$v.aux gen/$$v.xr.aux; \
	  done; test "$$(cat $(DOC_STATE) 2> /dev/null | md5sum || :)" != "$$before" \
	    || { echo "doc: both volumes settled in round $$round"; break; }; \
	done
	@! grep -E 'LaTeX Warning: (Reference|Citation).*undefined|There were undefined' \
	  doc/gen/avi.log doc/gen/avi-vol2.log \
	  || { echo "doc: undefined references (see doc/gen/avi.log, doc/gen/avi-vol2.log)"; false; }
	@! grep 'has been referenced but does not exist' doc/gen/avi.log doc/gen/avi-vol2.log \
	  || { echo "doc: links to nowhere (see doc/gen/avi.log, doc/gen/avi-vol2.log)"; false; }
	@grep -q '^\\gdef\\avivolone' doc/gen/avi.ext || { echo "doc: Volume I did not say where it ends"; false; }
	@awk '/^Overfull \\[hv]box \(/ { w = substr($$3, 2) + 0; if (w > 10) { print FILENAME ": " $$0; bad++ } } \
	  END { if (bad) { print "doc: " bad " overfull boxes over 10pt (see doc/gen/*.log)"; exit 1 } }' \
	  doc/gen/avi.log doc/gen/avi-vol2.log
	cp doc/gen/avi.pdf doc/avi.pdf && cp doc/gen/avi-vol2.pdf doc/avi-vol2.pdf

# The web edition (src/98-web.nw): TeX4ht on the same master, run in
# doc/gen/html where links put the master, its generated inputs and the
# figures where it expects them.  Its three passes and the conversion wait
# for nothing of the PDF and run beside its typesetting: every chunk number
# in the pages is a mark with the chunk's label (doc/preamble.tex), and
# make4ht copies the pages, the style sheet and the figures they use to
# doc/gen/html/pages.  Only the last step waits for the PDF: a copy of
# those pages becomes doc/html, html-chunks.awk writes the PDF's chunk
# numbers (gen/*.ext) into it, and html-linear.sh links the pages in
# reading order.  A TeX error in the last pass fails the build.
HTML_DEPS = doc/avi.tex doc/preamble.tex doc/indexes.tex doc/bibliography.tex $(WOVEN) \
	    doc/gen/values.tex $(FIGS:%=figures/%.png) $(PY_FIG).png doc/gen/bench.stamp doc/gen/concordance.tex \
	    tangle/weave/avi-html.cfg tangle/weave/avi-html.mk4
MAKE4HT = make4ht -e ../../../tangle/weave/avi-html.mk4 -c ../../../tangle/weave/avi-html.cfg
html: doc/html/avi.html
doc/gen/html/pages.stamp: $(HTML_DEPS) | $(B)/.deps-book
	rm -rf doc/gen/html && mkdir -p doc/gen/html
	for f in avi preamble indexes bibliography; do ln -s ../../$$f.tex doc/gen/html/$$f.tex; done \
	  && ln -s .. doc/gen/html/gen \
	  && ln -s ../../../figures doc/gen/html/figures
	cd doc/gen/html && $(MAKE4HT) -d pages avi.tex "xhtml,mathml,3" > make4ht.out 2>&1 \
	  || { tail -40 make4ht.out; false; }
	@! grep -A3 '^! ' doc/gen/html/avi.log || { echo "doc/html: TeX errors (see doc/gen/html/avi.log)"; false; }
	@test -s doc/gen/html/pages/avi.html || { echo "doc/html: make4ht wrote no avi.html"; false; }
	touch $@
doc/html/avi.html: doc/gen/html/pages.stamp doc/avi.pdf tangle/weave/html-chunks.awk tangle/weave/html-linear.sh
	rm -rf doc/html && cp -R doc/gen/html/pages doc/html
	awk -f tangle/weave/html-chunks.awk doc/gen/avi.ext doc/gen/avi-vol2.ext doc/html/*.html
	for f in doc/html/*.html; do mv "$$f.tmp" "$$f"; done
	@! grep -l "class='avi-chunk" doc/html/*.html || { echo "doc/html: chunk marks left in these pages"; false; }
	sh tangle/weave/html-linear.sh doc/html
	touch $@

# --- benchmarks -------------------------------------------------------------
# make bench: timings, never part of make or make check.  Each table records
# the machine and the flags it was measured with, and is typeset in the
# "Speed against accuracy" chapter of the PDF (rebuilt here).
CPUINFO = grep -m1 '^$(1)' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'
MACHINE = echo "\# cpu: $$($(call CPUINFO,model name)) (family $$($(call CPUINFO,cpu family)), model $$($(call CPUINFO,model[[:space:]])), $$($(call CPUINFO,cpu MHz)) MHz)"; \
	  echo "\# cores: $$(nproc)"; echo "\# compiler: $$($(CC) --version | head -1)"; \
	  echo "\# flags: $(CFLAGS)"
# A bench table gets the machine's record on top (STAMP: the program's
# temporary output, the table, and "show" to print it); a bench chart is
# drawn from figures/data into figures (PLOT).
STAMP = { $(MACHINE); cat $(1); } > $(2) && rm -f $(1)$(if $(3), && cat $(2))
# The cheapest run of each method for two targets, as a LaTeX table:
# $(1) the TSV (target, method, step, forces, seconds, ...), $(2) the table,
# $(3) what the targets bound, $(4) and $(5) the two targets.
CHEAPEST_TABLE = awk -F'\t' 'BEGIN { print "\\begin{center}\\small\\begin{tabular}{lrrrrrr}" ; \
	    print "method & \\multicolumn{3}{c}{$(3) $$$(4)$$} & \\multicolumn{3}{c}{$(3) $$$(5)$$}\\\\" ; \
	    print " & step & forces & s & step & forces & s\\\\ \\hline" } \
	  /^\043 cpu/ { cpu = substr($$0, 8) } /^\043 compiler/ { cc = substr($$0, 13) } /^\043/ { next } \
	  { if (!($$2 in row)) { order[++n] = $$2; row[$$2] = $$2 } \
	    for (i = 3; i <= 5; i++) row[$$2] = row[$$2] " & " ($$i == "nan" || $$i == "-" ? "--" : $$i) } \
	  END { for (i = 1; i <= n; i++) print row[order[i]] "\\\\"; \
	    print "\\end{tabular}\\\\[1ex] cheapest run of the sweep; " cpu "; " cc "\\end{center}" }' \
	  $(1) > $(2)
bench: $(BENCH_BIN) $(PY_PKG) tangle/bench/burrau_ensemble.py tangle/bench/python_speed.py tangle/bench/bench-kepler-wp.gp tangle/bench/bench-kepler-long.gp tangle/bench/bench-cubic-wp.gp \
	  tangle/bench/bench-threebody-wp.gp tangle/bench/bench-atlas.gp
	@mkdir -p figures/data doc/gen
	cut -d' ' -f1-3 /proc/loadavg > figures/data/load-start.txt
	{ $(MACHINE); $(B)/bench/bench-steps; } > figures/data/bench-steps.tsv
	{ $(MACHINE); $(B)/bench/bench-steps --load 2; } > figures/data/bench-steps-loaded.tsv
	cat figures/data/bench-steps.tsv
	$(B)/bench/bench-kepler-wp figures/data/wp.tmp figures/data/wp-needs.tmp
	$(call STAMP,figures/data/wp.tmp,figures/data/bench-kepler-wp.tsv)
	$(call STAMP,figures/data/wp-needs.tmp,figures/data/bench-kepler-wp-needs.tsv)
	$(B)/bench/bench-kepler-long figures/data/long.tmp figures/data/long-costs.tmp
	$(call STAMP,figures/data/long.tmp,figures/data/bench-kepler-long.tsv)
	$(call STAMP,figures/data/long-costs.tmp,figures/data/bench-kepler-long-costs.tsv,show)
	$(B)/bench/bench-cubic-wp figures/data/cubic.tmp figures/data/cubic-needs.tmp
	$(call STAMP,figures/data/cubic.tmp,figures/data/bench-cubic-wp.tsv)
	$(call STAMP,figures/data/cubic-needs.tmp,figures/data/bench-cubic-wp-needs.tsv,show)
	$(B)/bench/bench-threebody-wp figures/data/3b.tmp figures/data/3b-ref.tmp figures/data/3b-needs.tmp
	$(call STAMP,figures/data/3b.tmp,figures/data/bench-threebody-wp.tsv)
	$(call STAMP,figures/data/3b-ref.tmp,figures/data/bench-threebody-wp-reference.tsv,show)
	$(call STAMP,figures/data/3b-needs.tmp,figures/data/bench-threebody-wp-needs.tsv,show)
	$(B)/bench/bench-atlas figures/data/atlas.tmp figures/data/atlas-summary.tmp
	$(call STAMP,figures/data/atlas.tmp,figures/data/bench-atlas.tsv)
	$(call STAMP,figures/data/atlas-summary.tmp,figures/data/bench-atlas-summary.tsv,show)
	{ $(MACHINE); $(B)/bench/bench-pendulum; } | tee figures/data/bench-pendulum.tsv
	{ $(MACHINE); $(B)/bench/bench-pairs; } | tee figures/data/bench-pairs.tsv
	{ $(MACHINE); $(B)/bench/bench-logh; } | tee figures/data/bench-logh.tsv
	$(B)/bench/bench-targets figures/data/targets.tmp
	$(call STAMP,figures/data/targets.tmp,figures/data/bench-targets.tsv,show)
	$(SPLIT_BENCH)
	$(PY_BENCH)
	@mkdir -p $(REC)
	cp $(BENCH_TSV:%=figures/data/%.tsv) $(REC)/
	{ $(MACHINE); echo "# date: $$(date -u '+%F %T UTC')"; \
	  echo "# load average (1, 5, 15 min) at the start: $$(cat figures/data/load-start.txt)"; \
	  echo "# load average (1, 5, 15 min) at the end: $$(cut -d' ' -f1-3 /proc/loadavg)"; \
	  } > $(REC)/machine.txt
	rm -f doc/avi.pdf doc/avi-vol2.pdf && $(MAKE) --no-print-directory doc

# The Kepler splittings on the outer solar system, the planet with a companion
# and the Kozai triple (src/95-bench.nw), also alone: make bench-split runs
# them and records them, and only them, in $(REC).
SPLIT_BENCH = $(B)/bench/bench-split figures/data/split.tmp figures/data/split-sweeps.tmp \
	&& $(call STAMP,figures/data/split.tmp,figures/data/bench-split.tsv,show) \
	&& $(call STAMP,figures/data/split-sweeps.tmp,figures/data/bench-split-sweeps.tsv)
bench-split: $(B)/bench/bench-split
	@mkdir -p figures/data $(REC)
	$(SPLIT_BENCH)
	cp figures/data/bench-split.tsv figures/data/bench-split-sweeps.tsv $(REC)/

# The Python package's two benchmarks (src/95a-python.nw), also alone:
# make bench-python runs them and records them, and only them, in $(REC).
PY_BENCH = ( $(MACHINE); cd $(B)/python && PYTHONPATH=.:../../tangle/bench $(PYTHON) \
	  ../../tangle/bench/burrau_ensemble.py ) > figures/data/burrau-ensemble.tsv; \
	( $(MACHINE); cd $(B)/python && PYTHONPATH=.:../../tangle/bench $(PYTHON) \
	  ../../tangle/bench/python_speed.py ) | tee figures/data/python-speed.tsv
bench-python: $(PY_PKG) tangle/bench/burrau_ensemble.py tangle/bench/python_speed.py
	@mkdir -p figures/data $(REC)
	$(PY_BENCH)
	cp figures/data/burrau-ensemble.tsv figures/data/python-speed.tsv $(REC)/

# The record of the last make bench, committed: a plain make typesets its
# tables and draws its charts from it (doc/gen/bench.stamp), and the text
# quotes it through \val{bench-steps}{...} (doc/gen/bench-steps.summary).
REC       := doc/bench
BENCH_TSV := bench-steps bench-steps-loaded bench-kepler-wp bench-kepler-wp-needs \
             bench-kepler-long bench-kepler-long-costs bench-cubic-wp bench-cubic-wp-needs \
             bench-threebody-wp bench-threebody-wp-reference bench-threebody-wp-needs \
             bench-atlas bench-atlas-summary bench-pendulum bench-targets bench-pairs bench-logh \
             burrau-ensemble python-speed bench-split bench-split-sweeps
BENCH_GP  := $(patsubst %,tangle/bench/%.gp,bench-kepler-wp bench-kepler-long bench-cubic-wp \
             bench-threebody-wp bench-atlas burrau-ensemble)
PLOT  = gnuplot -e "datadir='$(REC)'; outdir='figures'" tangle/bench/$(1).gp
doc/gen/bench.stamp: $(BENCH_TSV:%=$(REC)/%.tsv) $(BENCH_GP) tangle/bench/bench-cubic-summary.awk \
  tangle/bench/gbs-targets.tsv tangle/bench/bench-choose.awk tangle/bench/bench-fails.awk \
  tangle/bench/bench-atlas-summary.awk tangle/bench/bench-logh-summary.awk tangle/bench/bench-logh-table.awk \
  tangle/bench/bench-split-table.awk tangle/bench/bench-split-summary.awk
	@mkdir -p doc/gen figures
	awk -F'\t' 'BEGIN { print "\\begin{center}\\small\\begin{tabular}{llrrrrrl}" ; \
	    print "problem & scheme & ns/step & ratio & min--max & loaded & forces/step & target\\\\ \\hline" } \
	  FNR == 1 { file++ } /^# cpu/ { cpu = substr($$0, 8) } /^# compiler/ { cc = substr($$0, 13) } /^#/ { next } \
	  file == 1 { loaded[$$1 " " $$2] = $$4; next } \
	  { printf "%s & %s & %s & %s & %s--%s & %s & %s & %s\\\\\n", $$1, $$2, $$3, $$4, $$5, $$6, loaded[$$1 " " $$2], $$7, ($$9 == "-" ? "" : $$9) } \
	  END { print "\\end{tabular}\\\\[1ex] per-thread processor time, 7 repetitions of $$10^6$$ steps, ratios to Verlet within each repetition (median, min--max); loaded: the median ratio with two spinning threads; " cpu "; " cc "\\end{center}" }' \
	  $(REC)/bench-steps-loaded.tsv $(REC)/bench-steps.tsv > doc/gen/bench-steps.tex
	$(call PLOT,bench-kepler-wp)
	$(call PLOT,burrau-ensemble)
	awk -F'\t' '!/^#/ { print $$1 "_min", $$2; print $$1 "_median", $$3 }' \
	  $(REC)/python-speed.tsv > doc/gen/python-speed.summary
	awk -F'\t' '!/^#/ { n++; ok += $$8 == "ok"; if ($$14 == 1) { c++; e[$$9]++ } } \
	  END { print "runs", n; print "ok", ok; print "failed", n - ok; print "converged", c; \
	        for (k = 0; k <= 3; k++) print "escaper_" k, e[k] + 0 }' \
	  $(REC)/burrau-ensemble.tsv > doc/gen/burrau-ensemble.summary
	awk -F'\t' '/^# cpu/ { cpu = substr($$0, 8) } /^# compiler/ { cc = substr($$0, 13) } /^#/ { next } \
	  { if (!($$1 in seen)) { seen[$$1] = 1; tg[++nt] = $$1 } \
	    if (!($$2 in row)) { order[++n] = $$2; row[$$2] = $$2 } \
	    row[$$2] = row[$$2] " & " ($$3 == "nan" ? "--" : $$3) " & " ($$4 == "nan" ? "--" : $$4) } \
	  END { printf "\\begin{center}\\footnotesize\\setlength{\\tabcolsep}{4pt}\\begin{tabular}{l"; for (i = 1; i <= nt; i++) printf "rr"; print "}"; \
	    printf "error"; for (i = 1; i <= nt; i++) printf " & \\multicolumn{2}{c}{%s}", tg[i]; print "\\\\"; \
	    printf "method"; for (i = 1; i <= nt; i++) printf " & forces & s"; print "\\\\ \\hline"; \
	    for (i = 1; i <= n; i++) print row[order[i]] "\\\\"; \
	    print "\\end{tabular}\\\\[1ex] " cpu "; " cc "\\end{center}" }' \
	  $(REC)/bench-kepler-wp-needs.tsv > doc/gen/bench-kepler-wp-needs.tex
	$(call PLOT,bench-kepler-long)
	awk -F'\t' 'BEGIN { print "\\begin{center}\\small\\begin{tabular}{rrrrrrrrr}" ; \
	    print "$$\\Delta s$$ & periods & error & \\multicolumn{2}{c}{av-dae} & tolerance & \\multicolumn{2}{c}{rk8pd} & ratio\\\\" ; \
	    print " & & & forces & s & & forces & s & forces, time\\\\ \\hline" } \
	  /^# cpu/ { cpu = substr($$0, 8) } /^# compiler/ { cc = substr($$0, 13) } /^#/ { next } \
	  { printf "%s & %s & %s & %s & %s & %s & %s & %s & %s, %s\\\\\n", $$1, $$2, $$3, $$4, $$5, $$6, $$8, $$9, $$10, $$11 } \
	  END { print "\\end{tabular}\\\\[1ex] " cpu "; " cc "\\end{center}" }' \
	  $(REC)/bench-kepler-long-costs.tsv > doc/gen/bench-kepler-long.tex
	$(call PLOT,bench-cubic-wp)
	$(call CHEAPEST_TABLE,$(REC)/bench-cubic-wp-needs.tsv,doc/gen/bench-cubic-wp-needs.tex,error,10^{-4},10^{-6})
	awk -F'\t' 'BEGIN { print "\\begin{center}\\small\\begin{tabular}{llrlrr}" ; \
	    print "check & role & forces & against & distance at $$t=10$$ & at $$t=30$$\\\\ \\hline" } \
	  /^# cpu/ { cpu = substr($$0, 8) } /^# compiler/ { cc = substr($$0, 13) } /^#/ || $$2 == "summary" { next } \
	  { printf "\\texttt{%s} & %s & %s & \\texttt{%s} & %s & %s\\\\\n", $$1, $$2, $$6, $$7, $$8, $$9 } \
	  END { print "\\end{tabular}\\\\[1ex] " cpu "; " cc "\\end{center}" }' \
	  $(REC)/bench-threebody-wp-reference.tsv > doc/gen/bench-threebody-wp-reference.tex
	$(call PLOT,bench-threebody-wp)
	$(call CHEAPEST_TABLE,$(REC)/bench-threebody-wp-needs.tsv,doc/gen/bench-threebody-wp-needs.tex,state error,10^{-2},10^{-4})
	$(call PLOT,bench-atlas)
	awk -F'\t' 'BEGIN { print "{\\footnotesize\\begin{longtable}{lllrrcr}" ; \
	    print "problem & scheme & monitor & largest stable & smallest unstable & monotone & with transients\\\\ \\hline\\endhead" } \
	  /^# cpu/ { cpu = substr($$0, 8) } /^# compiler/ { cc = substr($$0, 13) } /^#/ { next } \
	  { printf "%s & %s & %s & %s & %s & %s & %s\\\\\n", $$1, $$2, $$3, $$4, $$5, $$6, $$7 } \
	  END { print "\\end{longtable}}\\par\\noindent{\\small a dash: no such run in the strip; " cpu "; " cc "}\\par" }' \
	  $(REC)/bench-atlas-summary.tsv > doc/gen/bench-atlas.tex
	awk -F'\t' 'BEGIN { print "\\begin{center}\\small\\begin{tabular}{lrrrrrrr}" ; \
	    print "scheme & step & status & $$t$$ reached & steps & evaluations & max.\\ energy error & s\\\\ \\hline" } \
	  /^# order/ { note = substr($$0, 3) } /^# cpu/ { cpu = substr($$0, 8) } \
	  /^# compiler/ { cc = substr($$0, 13) } /^#/ { next } \
	  { printf "%s & %s & %s & %s & %s & %s & %s & %s\\\\\n", $$1, $$2, $$3, $$4, $$5, $$6, $$7, $$8 } \
	  END { print "\\end{tabular}\\\\[1ex] " note "; " cpu "; " cc "\\end{center}" }' \
	  $(REC)/bench-pendulum.tsv > doc/gen/bench-pendulum.tex
	awk -F'\t' 'BEGIN { print "{\\small\\begin{longtable}{lrrrrl}" ; \
	    print "method & parameter & forces & error & s & ratio to rk8pd, median (min--max)\\\\ \\hline\\endhead" } \
	  /^# largest/ { note = substr($$0, 3) } /^# cpu/ { cpu = substr($$0, 8) } \
	  /^# compiler/ { cc = substr($$0, 13) } /^#/ { next } \
	  { g = $$1 " " $$2 " " $$3; if (g != last) { last = g; \
	      printf "\\multicolumn{6}{l}{\\emph{%s to $$t_f=%s$$, error %s}}\\\\\n", $$1, $$2, $$3 } \
	    met = $$5 == 1; r = ($$11 == "nan" || $$4 == "rk8pd") ? "" : $$11 " (" $$10 "--" $$12 ")"; \
	    printf "\\quad %s & %s & %s & %s & %s & %s\\\\\n", $$4, (met ? $$6 : "--"), (met ? $$7 : "--"), \
	      $$8 (met ? "" : " (best)"), (met ? $$9 : "--"), r } \
	  END { print "\\end{longtable}}\\par\\noindent{\\small " note "; " cpu "; " cc "}\\par" }' \
	  $(REC)/bench-targets.tsv > doc/gen/bench-targets.tex
	awk -F'\t' 'FNR == 1 { file++ } /^#/ { next } \
	  { k = $$1 "_" $$2; gsub(/[^a-z0-9]+/, "_", k) } \
	  file == 1 { if ($$4 != "-") { print k "_loaded", $$4; L[k] = $$4 }; next } \
	  $$3 != "failed" { print k "_ns", $$3; print k "_ratio", $$4; \
	    print k "_ratio_min", $$5; print k "_ratio_max", $$6 } \
	  (k in L) && $$4 != "-" && $$4 > 0 { d = L[k] / $$4 - 1; if (d < 0) d = -d; \
	    if (d > mx) mx = d; sum += d; cnt++; if (d <= 0.03) within++ } \
	  END { print "load_diff_max_pct", 100 * mx; print "load_diff_mean_pct", 100 * sum / cnt; \
	    print "load_rows", cnt; print "load_rows_within_3pct", within }' \
	  $(REC)/bench-steps-loaded.tsv $(REC)/bench-steps.tsv > doc/gen/bench-steps.summary
	awk -F'\t' 'FNR == 1 { file++ } /^#/ { next } \
	  file == 1 && $$5 != "skipped" { k = "e" $$1 "_o" $$2 "_" $$3 "_" $$4; gsub(/[^a-z0-9]+/, "_", k); \
	    print k "_forces", $$7; print k "_seconds", $$8; print k "_energy", $$9; \
	    print k "_position", $$10; next } \
	  file == 2 && $$3 != "nan" { k = "need_" $$1 "_" $$2; gsub(/[^a-z0-9]+/, "_", k); \
	    print k "_forces", $$3; print k "_seconds", $$4 }' \
	  $(REC)/bench-kepler-wp.tsv $(REC)/bench-kepler-wp-needs.tsv > doc/gen/bench-kepler-wp.summary
	awk -F'\t' 'FNR == 1 { file++ } file == 1 && /^# method/ { sweep++ } /^#/ { next } \
	  file == 1 && $$3 != "skipped" { k = (sweep == 1 ? "t10_" : "t30_") $$1 "_" $$2; \
	    gsub(/[^a-z0-9]+/, "_", k); print k "_forces", $$5; print k "_seconds", $$7; \
	    print k "_energy_end", $$8; print k "_energy_max", $$9; print k "_state", $$10; next } \
	  file == 2 && $$4 != "-" { k = "need_" $$1 "_" $$2; gsub(/[^a-z0-9]+/, "_", k); \
	    print k "_forces", $$4; print k "_seconds", $$5 }' \
	  $(REC)/bench-threebody-wp.tsv $(REC)/bench-threebody-wp-needs.tsv > doc/gen/bench-threebody-wp.summary
	awk -F'\t' 'FNR == 1 { file++; split("dae_error dae_forces dae_s rk8pd_tol rk8pd_error rk8pd_forces rk8pd_s force_ratio time_ratio", col, " ") } /^#/ { next } \
	  file == 1 { k = "ds" $$1 "_t" $$2; gsub(/[^a-z0-9]+/, "_", k); \
	    for (i = 3; i <= 11; i++) if ($$i != "nan" && $$i != "-") print k "_" col[i - 2], $$i; next } \
	  { k = "ds" $$1 "_" $$2; gsub(/[^a-z0-9]+/, "_", k); end[k] = $$3; err[k] = $$4; \
	    if ($$3 == 10) at10[k] = $$4; if ($$4 > mx[k]) mx[k] = $$4 } \
	  END { for (k in end) { print k "_end_periods", end[k]; print k "_end_error", err[k]; \
	    print k "_max_error", mx[k]; if (k in at10) print k "_at10_error", at10[k] } }' \
	  $(REC)/bench-kepler-long-costs.tsv $(REC)/bench-kepler-long.tsv > doc/gen/bench-kepler-long.summary
	awk -F'\t' '/^# order/ { n = split($$0, w, /[^0-9.]+/); print "order", w[2]; print "steps_ratio", w[3]; \
	    print "evals_ratio", w[4]; print "time_ratio", w[5] } /^#/ { next } \
	  { k = $$1 == "midpoint-matching" ? "matching" : $$1 "_" $$2; gsub(/[^a-z0-9]+/, "_", k); \
	    print k "_step", $$2; print k "_t", $$4; print k "_steps", $$5; print k "_evals", $$6; \
	    print k "_error", $$7; print k "_s", $$8 }' \
	  $(REC)/bench-pendulum.tsv > doc/gen/bench-pendulum.summary
	awk -F'\t' 'BEGIN { print "\\begin{center}\\small\\begin{tabular}{rrrr}" ; \
	    print "$$N$$ & pairs & ns/pair, min & median\\\\ \\hline" } \
	  /^# spread/ { note = substr($$0, 3) } /^# cpu/ { cpu = substr($$0, 8) } \
	  /^# compiler/ { cc = substr($$0, 13) } /^#/ { next } \
	  { printf "%s & %s & %s & %s\\\\\n", $$1, $$2, $$3, $$4 } \
	  END { sub(/; sink.*/, "", note); \
	    print "\\end{tabular}\\\\[1ex] " note "; " cpu "; " cc "\\end{center}" }' \
	  $(REC)/bench-pairs.tsv > doc/gen/bench-pairs.tex
	awk -F'\t' '/^# spread/ { n = split($$0, w, /[^0-9.]+/); print "spread", w[2] } /^#/ { next } \
	  { print "n" $$1 "_min", $$3; print "n" $$1 "_median", $$4 }' \
	  $(REC)/bench-pairs.tsv > doc/gen/bench-pairs.summary
	awk -F'\t' '/^#/ { next } \
	  { k = $$1 "_t" $$2 "_" $$3 "_" $$4; gsub(/[^a-z0-9]+/, "_", k); print k "_met", $$5; \
	    if ($$13 != "") print k "_rejected", $$13; \
	    if ($$5 == 1) { print k "_forces", $$7; print k "_seconds", $$9; \
	      if ($$11 != "nan") print k "_ratio", $$11 } \
	    if ($$8 != "inf") print k "_error", $$8 }' \
	  $(REC)/bench-targets.tsv > doc/gen/bench-targets.summary
	awk -F'\t' 'BEGIN { print "\\begin{center}\\footnotesize\\setlength{\\tabcolsep}{4pt}\\begin{tabular}{lrrrrrrll}" ; \
	    print "problem & $$t_f$$ & error & at most & logh-gbs & ttl-gbs & rk8pd & \\multicolumn{2}{l}{time ratios}\\\\ \\hline" } \
	  /^# cpu/ { cpu = substr($$0, 8) } /^#/ { next } \
	  FNR == NR { split($$0, f, /[ \t]+/); k = f[1] " " f[2] " " f[3]; want[++n] = k; most[k] = f[4]; next } \
	  $$4 ~ /-gbs$$/ || $$4 == "rk8pd" { k = $$1 " " $$2 " " $$3; \
	    cell[k, $$4] = ($$5 == 1 ? $$7 : "-- (" $$8 ")") ($$13 != "" ? sprintf(" [%.0f\\%%]", 100 * $$13) : ""); if ($$4 != "rk8pd" && $$5 == 1 && $$11 != "nan") r[k, $$4] = $$11 } \
	  END { for (i = 1; i <= n; i++) { k = want[i]; split(k, w, " "); \
	      printf "%s & %s & %s & %s & %s & %s & %s & %s & %s\\\\\n", w[1], w[2], w[3], most[k], cell[k, "logh-gbs"], \
	        cell[k, "ttl-gbs"], cell[k, "rk8pd"], r[k, "logh-gbs"], r[k, "ttl-gbs"] } \
	    print "\\end{tabular}\\\\[1ex] forces, or the best error reached (--); in brackets the share of attempts rejected; " cpu "\\end{center}" }' \
	  tangle/bench/gbs-targets.tsv $(REC)/bench-targets.tsv > doc/gen/gbs-targets.tex
	awk -f tangle/bench/bench-choose.awk $(REC)/bench-kepler-wp-needs.tsv \
	  $(REC)/bench-threebody-wp-needs.tsv $(REC)/bench-cubic-wp-needs.tsv \
	  $(REC)/bench-targets.tsv $(REC)/bench-split.tsv > doc/gen/bench-choose.tex
	awk -f tangle/bench/bench-fails.awk $(REC)/bench-atlas-summary.tsv > doc/gen/bench-fails.tex
	awk -f tangle/bench/bench-cubic-summary.awk $(REC)/bench-cubic-wp.tsv \
	  $(REC)/bench-cubic-wp-needs.tsv > doc/gen/bench-cubic-wp.summary
	awk -f tangle/bench/bench-atlas-summary.awk $(REC)/bench-atlas.tsv \
	  $(REC)/bench-atlas-summary.tsv > doc/gen/bench-atlas.summary
	awk -f tangle/bench/bench-logh-summary.awk $(REC)/bench-logh.tsv > doc/gen/bench-logh.summary
	awk -f tangle/bench/bench-logh-table.awk $(REC)/bench-logh.tsv > doc/gen/bench-logh.tex
	awk -f tangle/bench/bench-split-table.awk $(REC)/bench-split.tsv > doc/gen/bench-split.tex
	awk -f tangle/bench/bench-split-summary.awk $(REC)/bench-split.tsv > doc/gen/bench-split.summary
	touch $@
# The stamp's recipe writes these summaries.  The empty recipe (;) makes
# make look at them again after it, so that values.tex, which depends on
# them, is rebuilt in the same run when a record changed (without it,
# a changed bench record reached the text only at the next make).
doc/gen/bench-steps.summary doc/gen/bench-kepler-wp.summary doc/gen/bench-threebody-wp.summary \
  doc/gen/bench-kepler-long.summary doc/gen/bench-pendulum.summary \
  doc/gen/bench-cubic-wp.summary doc/gen/bench-atlas.summary \
  doc/gen/bench-pairs.summary doc/gen/bench-targets.summary doc/gen/bench-logh.summary \
  doc/gen/python-speed.summary doc/gen/burrau-ensemble.summary doc/gen/bench-split.summary: doc/gen/bench.stamp ;

# --- memcheck ---------------------------------------------------------------
# make memcheck: every unit test and every figure program (with its defaults,
# writing into a temporary directory) under valgrind; any error, or a leak
# that is definitely lost, fails it.  Not part of make check: it takes about
# twenty-seven minutes (rf-fig1's grid alone, eight; kozai-lidov and
# outer-solar, five and four; measured, all clean).
VALGRIND = valgrind -q --error-exitcode=9 --leak-check=full --errors-for-leak-kinds=definite
memcheck: $(TEST_BIN) $(FIG_BIN)
	@command -v valgrind > /dev/null || { echo "make memcheck needs valgrind (apt-get install valgrind)"; exit 2; }
	@tmp=$$(mktemp -d); fail=0; \
	for t in $(filter $(B)/test/test-%,$(TEST_BIN)) $(FIG_BIN); do \
	  case $$t in */fig/*) args="--out $$tmp";; *) args=;; esac; \
	  if $(VALGRIND) $$t $$args > /dev/null 2> $$tmp/err; then echo "ok - $$t"; \
	  else echo "not ok - $$t"; grep -v '^\[' $$tmp/err | head -20; fail=1; fi; \
	done; rm -rf $$tmp; exit $$fail

# --- install ---------------------------------------------------------------
# make install PREFIX=... LIBDIR=... DESTDIR=...: the libraries, the public
# headers (in include/avi), the pkg-config file, the avi program and its man
# page, the licence, and the woven PDF's two volumes if they have been built
# (make install-doc builds and installs them), and the Python package avi in
# PYDIR with the LIBDIR it loads the library from (_where.py); make uninstall
# removes exactly these
# (src/99b-cli.nw).  LIBDIR may be Debian's multiarch path,
# e.g. LIBDIR=/usr/lib/x86_64-linux-gnu.  Installed as root with no DESTDIR,
# the shared library is made known to the dynamic linker by $(LDCONFIG).
PREFIX  ?= /usr/local
# the Python package: where Debian's python3 looks under PREFIX
PYDIR   ?= $(PREFIX)/lib/$(shell $(PYTHON) -c 'import sys; print("python%d.%d" % sys.version_info[:2])')/dist-packages
LIBDIR  ?= $(PREFIX)/lib
DESTDIR ?=
LDCONFIG ?= ldconfig
VERSION  = $(shell sed -n 's/^\#define AVI_VERSION "\(.*\)"/\1/p' tangle/lib/avi-version.h)
PUBLIC_H = tangle/lib/avi.h $(wildcard tangle/lib/avi-*.h)
DOCDIR   = $(PREFIX)/share/doc/avi
INSTALLED = $(addprefix $(LIBDIR)/,libavi.a libavi.so libavi.so.0 libavi.so.$(VERSION) \
	      pkgconfig/avi.pc) \
	    $(addprefix $(PREFIX)/,bin/avi share/man/man1/avi.1 \
	      $(patsubst tangle/lib/%,include/avi/%,$(PUBLIC_H))) \
	    $(DOCDIR)/avi.pdf $(DOCDIR)/avi-vol2.pdf $(DOCDIR)/COPYING
install: $(B)/libavi.a $(B)/libavi.so tangle/lib/avi.pc.in $(CLI_BIN) $(PY_SRC)
	install -d $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(PREFIX)/include/avi \
	  $(DESTDIR)$(DOCDIR) $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 $(B)/cli/avi $(DESTDIR)$(PREFIX)/bin/avi
	install -m 644 tangle/cli/avi.1 $(DESTDIR)$(PREFIX)/share/man/man1/avi.1
	install -m 644 $(B)/libavi.a $(DESTDIR)$(LIBDIR)/libavi.a
	install -m 755 $(B)/libavi.so $(DESTDIR)$(LIBDIR)/libavi.so.$(VERSION)
	ln -sf libavi.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libavi.so.0
	ln -sf libavi.so.0 $(DESTDIR)$(LIBDIR)/libavi.so
	install -m 644 $(PUBLIC_H) $(DESTDIR)$(PREFIX)/include/avi/
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@LIBDIR@|$(LIBDIR)|' -e 's|@VERSION@|$(VERSION)|' \
	  tangle/lib/avi.pc.in > $(DESTDIR)$(LIBDIR)/pkgconfig/avi.pc
	install -m 644 COPYING $(DESTDIR)$(DOCDIR)/COPYING
	for v in avi avi-vol2; do if [ -f doc/$$v.pdf ]; then \
	  install -m 644 doc/$$v.pdf $(DESTDIR)$(DOCDIR)/$$v.pdf; fi; done
	install -d $(DESTDIR)$(PYDIR)/avi
	install -m 644 $(PY_SRC) $(DESTDIR)$(PYDIR)/avi/
	echo 'LIBDIR = "$(LIBDIR)"  # written by make install' > $(DESTDIR)$(PYDIR)/avi/_where.py
	if [ -z "$(DESTDIR)" ] && [ "$$(id -u)" = 0 ]; then $(LDCONFIG); fi

install-doc: doc/avi.pdf doc/avi-vol2.pdf
	install -d $(DESTDIR)$(DOCDIR)
	install -m 644 doc/avi.pdf doc/avi-vol2.pdf $(DESTDIR)$(DOCDIR)/

uninstall:
	rm -f $(addprefix $(DESTDIR),$(INSTALLED))
	rm -rf $(DESTDIR)$(PYDIR)/avi
	-rmdir $(DESTDIR)$(PREFIX)/include/avi $(DESTDIR)$(DOCDIR) 2>/dev/null

# --- tests ------------------------------------------------------------------
check: $(TEST_BIN) $(CLI_BIN) $(EXAMPLE_BIN) $(PY_PKG) $(FIGS:%=figures/data/%.summary) figures doc/html/avi.html \
  | $(B)/.deps-check
	@PYTHON=$(PYTHON) tests/check.sh $(B) $(NW)

record: $(FIGS:%=figures/data/%.summary)
	tests/golden.sh record

clean:
	rm -rf build build-san figures/*.pdf figures/*.png figures/data doc/gen doc/avi.pdf doc/avi-vol2.pdf doc/html
	find tangle -mindepth 1 ! -name README.md ! -name .gitignore -delete
