#!/usr/bin/env bash
# tests/prose-numbers.sh FILE.nw LABEL ALLOWED...
# The prose of the section \label{LABEL} of FILE.nw (its text, not its
# code chunks) may quote a measured number only through \val or \valfull,
# which read the recorded bench run.  Whole numbers (counts, exponents,
# repetitions) are the experiment's design; every decimal number left in
# the prose must be one of ALLOWED: the experiment's parameters and the
# targets, which the text states, not measures.  Prints one TAP line.
set -u
file=$1 label=$2; shift 2
allowed=" $* "
bad=$(awk -v label="$label" '
  /^\\(chapter|section)\{/ { on = 0 }
  index($0, "\\label{" label "}") { on = 1 }
  /^<<.*>>=$/ { code = 1; next }
  /^@/ { code = 0; next }
  on && !code {
    line = $0
    gsub(/\\val(full)?\{[^}]*\}\{[^}]*\}/, "", line)
    gsub(/\\(ref|label|input|IfFileExists|includegraphics|cite)\{[^}]*\}/, "", line)
    gsub(/\[\[[^]]*\]\]/, "", line)
    gsub(/\\[A-Za-z]+/, " ", line)
    while (match(line, /[0-9]+\.[0-9]+/)) {
      print NR ":" substr(line, RSTART, RLENGTH)
      line = substr(line, RSTART + RLENGTH)
    }
  }' "$file" | while IFS=: read -r n x; do
    case $allowed in *" $x "*) ;; *) echo "line $n: $x";; esac
  done)
if [ -z "$bad" ]; then
  echo "ok - $label: every measured number in the prose comes from the record"
else
  echo "not ok - $label: numbers typed in the prose: $(echo $bad)"
fi
