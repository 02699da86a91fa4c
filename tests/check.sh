#!/usr/bin/env bash
# The test driver of `make check`:  tests/check.sh BUILD_DIR SRC.nw...
# Runs eight kinds of check, prints one "ok"/"not ok" line per check, and
# closes with the line "N passed, N failed, N skipped".
#
# A check that could not run says so in TAP's way, "ok - what # SKIP why",
# and is counted as skipped, never as passed.  Under CI (CI set and not
# "false"), where `make` and `make check` have installed everything the
# tests use, a skip is a failure unless its reason says why CI may skip
# it, with the words "ci-ok:" and the justification.
set -u
cd "$(dirname "$0")/.."
build=$1; shift
pass=0; fail=0; skip=0
in_ci=; case ${CI:-} in ''|false|0) ;; *) in_ci=1;; esac
count() {   # read TAP-like lines on stdin, echo them, count them
  while IFS= read -r line; do
    case $line in
      'ok '*'# SKIP'*|'ok '*'# skip'*)
        if [ -n "$in_ci" ] && [[ $line != *ci-ok:* ]]; then
          echo "not ok${line#ok} (a skip under CI)"; fail=$((fail + 1))
        else
          echo "$line"; skip=$((skip + 1))
        fi;;
      'ok '*) echo "$line"; pass=$((pass + 1));;
      'not ok'*) echo "$line"; fail=$((fail + 1));;
      *) echo "$line";;
    esac
  done
}

# 1. Every root chunk must be an output file.  A chunk whose name is
#    misspelled where it is defined is never used, so it becomes a root: it
#    shows up here as a name that is not a path the build knows.  (The one
#    file of test/ that is no test is ckpt-sign.c, the CLI tests' forger;
#    the one header of bench/ is kit.h, the benchmarks' kit's.)
echo "# root chunks"
odd=$(noroots "$@" | sed -e 's/^<<//' -e 's/>>$//' | grep -Ev \
  '^(lib/((problems|schemes|time|driver)/)?[a-z0-9-]+\.[ch]|ref/[a-z0-9-]+\.[ch]|lib/avi\.pc\.in|examples/[a-z0-9-]+\.(c|cc|txt)|test/ckpt-sign\.c|cli/([a-z]+\.c|cli\.h|avi\.1)|figkit/[a-z0-9-]+\.[ch]|fig/[a-z0-9-]+\.(c|gp)|test/test-[a-z0-9-]+\.(c|sh)|golden/[a-z0-9-]+\.tol|bench/([a-z0-9-]+\.(c|gp|awk|tsv)|[a-z_]+\.py|kit\.h)|weave/[a-z0-9-]+\.(awk|cfg|mk4|html|sh|py)|python/(avi/(_?[a-z]+|__init__)|tests/test_[a-z_]+|examples/[a-z_]+)\.py|python/layout\.c)$')
if [ -z "$odd" ]; then
  count <<< "ok - every root chunk names an output file"
else
  count <<< "not ok - root chunks that are not output files (misspelled?): $(echo $odd)"
fi

# 1b. Every root chunk must have been tangled to its file.
missing=$(noroots "$@" | sed -e 's/^<<//' -e 's/>>$//' | while read -r r; do
  [ -f "tangle/$r" ] || echo "$r"; done)
if [ -z "$missing" ]; then
  count <<< "ok - every root chunk is tangled to its file"
else
  count <<< "not ok - root chunks with no tangled file: $(echo $missing)"
fi

# 2. Unit tests: each cmocka program reports in TAP.  A program that exits
#    non-zero without a failing test (a crash) counts as one failure.
for t in "$build"/test/test-*; do
  case $t in *.o|*.d) continue;; esac
  echo "# $(basename "$t")"
  out=$(CMOCKA_MESSAGE_OUTPUT=TAP "$t" 2>&1); rc=$?
  count < <(grep -E '^(ok|not ok) ' <<< "$out" | sed "s/^\(ok\|not ok\) [0-9]* - /\1 - $(basename "$t"): /")
  grep -E '^# .*(error|Failure)' <<< "$out" || true
  if [ $rc -ne 0 ] && ! grep -q '^not ok' <<< "$out"; then
    count <<< "not ok - $(basename "$t") exited with status $rc"
    tail -5 <<< "$out"
  fi
done

# 3. Command-line tests: each tangle/test/test-<id>-*.sh receives the path
#    of figure program <id> and reports in TAP.
for t in tangle/test/test-*.sh; do
  [ -f "$t" ] || continue
  id=$(basename "$t" .sh); id=${id#test-}; id=${id%-*}
  echo "# $(basename "$t")"
  count < <(bash "$t" "$build/fig/$id" 2>&1 | grep -E '^(ok|not ok) ' \
            | sed "s/^\(ok\|not ok\) [0-9]* - /\1 - /")
done

# 3b. The Python package (src/95a-python.nw), its tests under pytest
#     (src/99c-python-tests.nw), against build/python: one line per test.
#     A library built with the sanitizers (make check SANITIZE=1) needs their
#     runtimes loaded first into Python, which is not built with them; Python's
#     own allocations, freed at exit or never, are not the library's leaks.
echo "# python: pytest"
san=; case $build in *-san) san="$(${CC:-cc} -print-file-name=libasan.so) $(${CC:-cc} -print-file-name=libubsan.so)";; esac
out=$(cd "$build/python" && LD_PRELOAD=$san ASAN_OPTIONS=detect_leaks=0 \
      PYTHONPATH=. ${PYTHON:-/usr/bin/python3} -m pytest -v -p no:cacheprovider \
      -W ignore::DeprecationWarning ../../tangle/python/tests 2>&1); rc=$?
tap=$(sed -n -e 's/^\(.*::.*\) PASSED.*/ok - python: \1/p' \
             -e 's/^\(.*::.*\) \(FAILED\|ERROR\).*/not ok - python: \1/p' \
             -e 's/^ERROR \(.*\)/not ok - python: \1/p' \
             -e 's/^\(.*::.*\) SKIPPED.*/ok - python: \1 # SKIP/p' <<< "$out")
count <<< "$tap"
#     pytest's own count must be the lines read, and its status clean
said=$(tail -1 <<< "$out" | grep -oE '[0-9]+ (passed|failed|skipped|error)' | awk '{ n += $1 } END { print n + 0 }')
if [ "$rc" = 0 ] && [ "$said" = "$(grep -c . <<< "$tap")" ]; then
  count <<< "ok - python: pytest ran $said tests, each read above"
else
  count <<< "not ok - python: pytest exit $rc, $said tests, $(grep -c . <<< "$tap") read: $(tail -3 <<< "$out")"
fi

# 4. Golden files: the figure data against tests/golden, by numdiff.
echo "# golden files"
count < <(tests/golden.sh compare)

# 5. The build itself: a user who is neither root nor has sudo, missing a
#    package, gets the apt-get command to run and exit 2, from make deps
#    and from the stamps of the book's and of make check's packages alike.
#    The user is played by a PATH with no sudo on it and an `id` that
#    answers 1000.
echo "# the build"
deps_test() {   # deps_test TARGET WHAT MAKE-VARIABLES...
  local tmp rc out target=$1 what=$2; shift 2
  tmp=$(mktemp -d) && mkdir "$tmp/b" "$tmp/bin" || return 1
  for c in dpkg-query grep mkdir touch bash; do ln -s "$(command -v "$c")" "$tmp/bin/$c"; done
  printf '#!/bin/sh\necho 1000\n' > "$tmp/bin/id" && chmod +x "$tmp/bin/id"
  out=$(env PATH="$tmp/bin" "$(command -v make)" -s --no-print-directory "${target//@/$tmp}" \
        B="$tmp/b" "$@" 2>&1); rc=$?
  rm -rf "$tmp"
  if [ $rc = 2 ] && grep -q "^make: missing Debian packages; as root, run: apt-get install .*avi-no-such-package" <<< "$out"
  then echo "ok - without root or sudo, $what names the apt-get command and exits 2"
  else echo "not ok - without root or sudo, $what exits $rc: $out"; fi
}
count < <(deps_test deps "make" DEB_PKGS="avi-no-such-package")
count < <(deps_test @/b/.deps-book "make, for the book's packages," DEB_PKGS= DEB_BOOK_PKGS="avi-no-such-package")
count < <(deps_test @/b/.deps-check "make check" DEB_PKGS= DEB_BOOK_PKGS= DEB_CHECK_PKGS="avi-no-such-package")

# 6. Part III's summary and the Speed chapter quote measured numbers only from
#    the recorded bench run (doc/bench, through \val), and the cost guard's from its pinned
#    table: each section with the decimal parameters, targets and equation
#    numbers its text states.
echo "# numbers in the prose"
count < <(tests/prose-numbers.sh src/94-references.nw ch:findings)
count < <(tests/prose-numbers.sh src/94-references.nw sec:bench-choose 0.99)
count < <(tests/prose-numbers.sh src/94-references.nw sec:bench-fails 0.1)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:cost-guard \
            0.5 0.01 0.4 0.1 0.05 0.3 4.18)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-steps \
            0.5 0.01 0.4 0.1 1.6 2.5 1.3 2.6 3.9 1.25 2.0 1.8 3.361)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-targets \
            0.99 4.5 1.2 1.25 0.9)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-wp \
            0.5 0.9 0.99 0.999 0.1 0.001 0.8 0.01 0.002 99.5)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-three-body \
            3.361 0.1 0.05 0.04 0.02 0.01 0.005 0.002 0.001 0.000625)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-long \
            1.09 0.3 0.99 0.05 0.01 0.002)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-pendulum)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-logh 0.99 0.01 0.1 1.3 0.08 0.115)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-atlas \
            0.1 0.99 0.009 0.3 0.5 0.4 1.05134 1.05 0.01 1.2 3.2 5.623 0.18 0.32 0.56)
count < <(tests/prose-numbers.sh src/95-bench.nw sec:bench-cubic \
            0.3 0.054 0.5 0.25 0.8 0.4 0.2 0.002 0.001 1.0512 1.0524 0.28 0.41)
#    The worked examples in space (src/93b-space.nw) quote their figures'
#    summaries the same way: the decimals left are the triples' alpha and
#    e0, Mardling and Aarseth's coefficient, the book's section number,
#    data and Pluto's mass, the claims' thresholds, the bound on the
#    sweep's eps_SA and the obliquity.
count < <(tests/prose-numbers.sh src/93b-space.nw sec:kozai 0.005 0.01 0.02 0.05 2.8 0.1)
count < <(tests/prose-numbers.sh src/93b-space.nw sec:outer-solar \
            2.4 1.00000597682 2.95912208286 1.5 1.3 23.4392911)
#    The hierarchical triple (src/86-hierarchical.nw): the pericentre 0.1,
#    the target's 2.5e5 forces, the rotation step 0.7 of its starts, and
#    IAS15's numbers as issue 34 reports them (2.4e5, 3.6e-12, 1.2e-10).
count < <(tests/prose-numbers.sh src/86-hierarchical.nw sec:hier-triple \
            0.1 2.5 0.7 2.4 3.6 1.2)

# 7. The web edition, read in headless Chromium (src/98-web.nw): every page
#    loads without console messages, its equations are laid out as MathML,
#    no text of a formula is outside MathML's token elements, every number
#    from the value macros reads as the PDF sets it (and all of them are
#    there), its images load, its prose has no raw LaTeX, every link within the book
#    resolves, the book has all its pages, and a screenshot of the page with
#    most displayed equations is not blank.
echo "# the web edition"
ix_pages() { echo $(( ($(grep -c "^\\\\nwixlogsorted{$1}" doc/gen/woven-ix.tex) - 1) / 200 )); }
book_pages=$(( $(grep -cE '^\\(part|chapter|section)\*?\{' doc/gen/woven.tex) \
               + $(cat doc/indexes.tex doc/bibliography.tex | grep -cE '^\\chapter\*\{') + $(ix_pages c) + $(ix_pages i) + 1 ))
book_values=$(cat doc/gen/woven-1.tex doc/gen/woven-2.tex | grep -o '\\val\(full\)\?{' | wc -l)
count < <(bash tangle/weave/html-check.sh doc/html "$build/web" "$book_pages" "$book_values")

# 8. The figures are lettered in the document's typeface: every font that a
#    figure's PDF embeds is Latin Modern (the text face, or its math face for
#    lowercase Greek).  A font that is missing would fall back silently to
#    another; so would a label written in a face the scripts do not set.
echo "# figure fonts"
figure_fonts() {
  local f fonts other bad=
  for f in figures/*.pdf; do
    fonts=$(grep -a -o '/BaseFont */[A-Za-z0-9+-]*' "$f" | sed -e 's|.*/||' -e 's/^[A-Z]\{6\}+//' | sort -u)
    other=$(grep -v -E '^(LMRoman|LatinModernMath)' <<< "$fonts")
    if ! grep -q '^LMRoman' <<< "$fonts" || [ -n "$other" ]; then
      bad="$bad $(basename "$f") (${other:-no Latin Modern})"; fi
  done
  if [ -z "$bad" ]; then echo "ok - every figure is lettered in Latin Modern only"
  else echo "not ok - figures lettered in other faces:$bad"; fi
}
count < <(figure_fonts)
#    ... and printed large enough to read: every run of text at 8 points or
#    more, sub- and superscripts at 0.8 of that (src/96-figkit.nw), measured
#    in each figure's PDF at the width the book prints it.
count < <(python3 tangle/weave/figure-lettering.py doc/gen/figure-widths-avi.txt figures/*.pdf)

# 9. The identifier index and the chunks' footers list C only
#    (weave/c-index.awk, src/95b-concordance.nw): a chunk tangled into a file that
#    is not C or C++ (a shell test, a gnuplot script, the manual page) is no
#    use of a C identifier and has no "Uses" list, while the C files' chunks do.
echo "# identifier index"
c_only_index() {
  awk '/\\nwnotused\{/ { f = $0; sub(/.*\\nwnotused\{/, "", f); sub(/\}.*/, "", f)
         uses = /\\nwidentuses|\\nwindexuse/
         if (f ~ /\.([ch]|cc)$/) { c++; cu += uses } else { o++; if (uses) bad = bad " " f } }
       END { if (bad == "" && o > 0 && cu > 0)
               print "ok - " o " files that are not C list no C uses (" cu " of " c " C files do)"
             else print "not ok - uses of C identifiers listed in files that are not C:" bad \
               " (" o " such files, " cu " C files with uses)" }' doc/gen/woven.tex
}
count < <(c_only_index)

#    The filter on a small web: a library file whose comment says "steps", a
#    test program that defines a helper steps and calls the library's
#    lib_fn, and a shell script that names both.  Only the test's call of
#    lib_fn is a use; the comment's word and the script's words are not.
c_index_scope() {
  local tmp out; tmp=$(mktemp -d)
  printf '%s\n' '@ A small web.' '<<lib/x.c>>=' '/* one of the library'"'"'s steps */' \
    'int lib_fn(void) { return 1; }' '@ %def lib_fn' '<<test/t.c>>=' \
    'static int steps(void) { return lib_fn(); }' '@ %def steps' '<<test/t.sh>>=' \
    'echo steps lib_fn' '@' > "$tmp/t.nw"
  noweave -n -filter 'awk -v kind=defn -f tangle/weave/c-index.awk' -index \
    -filter 'awk -v kind=use -f tangle/weave/c-index.awk' "$tmp/t.nw" > "$tmp/t.tex" 2>&1
  out=$(awk '/\\nwnotused\{/ { f = $0; sub(/.*\\nwnotused\{/, "", f); sub(/\}.*/, "", f)
               n = gsub(/\\nwindexuse\{/, "&"); printf "%s:%d ", f, n }' "$tmp/t.tex")
  if [ "$out" = "lib/x.c:0 test/t.c:1 test/t.sh:0 " ] && grep -q 'nwindexuse{\\nwixident{lib{\\_}fn}}' "$tmp/t.tex"
  then echo "ok - the index keeps a program's use of the library and drops words: $out"
  else echo "not ok - the uses per file should be lib/x.c:0 test/t.c:1 test/t.sh:0, are: $out"; fi
  rm -rf "$tmp"
}
count < <(c_index_scope)

echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]
