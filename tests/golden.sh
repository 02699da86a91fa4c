#!/usr/bin/env bash
# Golden-file driver.
#
#   tests/golden.sh compare   compare figures/data with tests/golden; print one
#                             "ok - ..." or "not ok - ..." line per file
#   tests/golden.sh record    copy figures/data into tests/golden
#
# Which files are golden, and with which numdiff tolerances, is not decided
# here: each tangle/golden/<id>.tol is tangled from the appendix chapter on
# claims and golden files (src/97-claims.nw), where the tolerances are argued.  Its lines read
#     FILE  NUMDIFF-OPTIONS...
# with FILE a name in figures/data/.  Lines that start with '#' are comments.
# Timing keys (wall_s, and any key that starts with wall_) vary from run
# to run and are never compared; nor are keys that start with roundoff_,
# numbers that measure roundoff itself (another compiler changes them by
# their own size), which their figure's claims test bounds instead.
set -u
cd "$(dirname "$0")/.."
mode=${1:-compare}
fresh=figures/data
gold=tests/golden
strip_timing() { grep -v -e '^wall_' -e '^roundoff_' "$1" || true; }

tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
shopt -s nullglob
tols=(tangle/golden/*.tol)
[ ${#tols[@]} -gt 0 ] || { echo "not ok - no tangle/golden/*.tol files"; exit 1; }
named=()
while read -r file opts; do
  case $file in ''|'#'*) continue;; esac
  named+=("$file")
  if [ "$mode" = record ]; then
    strip_timing "$fresh/$file" > "$gold/$file"
    echo "recorded $gold/$file"
    continue
  fi
  if [ ! -f "$gold/$file" ]; then
    echo "not ok - golden $file: tests/golden/$file is missing (make record?)"
  elif [ ! -f "$fresh/$file" ]; then
    echo "not ok - golden $file: figures/data/$file was not produced"
  else
    # numdiff needs files it can seek in, not pipes
    strip_timing "$gold/$file" > "$tmp/golden"
    strip_timing "$fresh/$file" > "$tmp/fresh"
    if numdiff -q $opts "$tmp/golden" "$tmp/fresh" > /dev/null 2>&1; then
      echo "ok - golden $file ($opts)"
    else
      echo "not ok - golden $file ($opts) differs:"
      numdiff -S $opts "$tmp/golden" "$tmp/fresh" 2>&1 | tail -25 | sed 's/^/#   /'
    fi
  fi
done < <(cat "${tols[@]}")

# A golden file that no .tol names would never be compared: report it.
[ "$mode" = record ] && exit 0
for g in "$gold"/*; do
  b=$(basename "$g")
  printf '%s\n' "${named[@]}" | grep -qxF "$b" \
    && continue
  echo "not ok - golden $b has no tolerance line in any tangle/golden/*.tol"
done
exit 0
