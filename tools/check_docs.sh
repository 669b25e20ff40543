#!/usr/bin/env bash
# ctest repository.docs-current: the documentation still matches the code. Usage: tools/check_docs.sh ROOT
#
# Checks, in README.md, docs/*.md, docs/workbook/*.md and docs/course/*.md:
#  1. every repository path written in backticks (under framework/, labs/, tests/, tools/, resources/,
#     docs/, cmake/ or bench/, with a file extension) exists; placeholders (FILE.json, <lab>, *) are skipped;
#  2. each workbook exercise heading (### TAG: ... (`ode/file.cpp`, `function`)) names a file that exists
#     under framework/physics/ and a function defined there (anywhere in framework/physics/ when the
#     heading names no file);
#  3. figures quoted from the code, each read from the code here, never written into this script:
#     - "N solution blocks" in docs/instructor-guide.md: the "// BEGIN SOLUTION" lines of the .cpp and .h
#       files, counted as tools/student_release.sh counts them (skipped in a hand-out, which has none);
#     - "packages: all N installed" in chapter 0: the length of PBA_PACKAGES in tools/driver_lib.sh;
#     - the exit code of a run paused by the instability guard, wherever a clause mentions the guard
#       and an exit code: kExitGuardPaused in framework/app/lab.h;
#  4. no page says that a lab which exists in labs/ is "not yet written";
#  5. in docs/course/*.md, a line that lists exercise tags and ends them with "(N min)" gives N as the sum of
#     those tags' minutes in resources/exercises.tsv; "All N exercises come to M min" gives the catalog's
#     count and total; the syllabus's week table lists every exercise of the catalog exactly once;
#  6. a row of ./pba grade's table shown in a code block (tag, title, TIME, pass or FAIL, hint) has the
#     catalog's title and minutes, and a FAIL row the catalog's hint.
# Prints one line per problem (FILE:LINE: what) and exits 1 when there is any.
set -uo pipefail
root="${1:?usage: tools/check_docs.sh ROOT}"
cd "$root" || { echo "check_docs: no directory $root"; exit 2; }

problems=0
problem() { echo "$1"; problems=$((problems + 1)); }

docs=()
for f in README.md docs/*.md docs/workbook/*.md docs/course/*.md; do [[ -f "$f" ]] && docs+=("$f"); done
workbook=(docs/workbook/*.md)
chapter0="$(ls docs/workbook/00-*.md 2>/dev/null | head -n 1)"
labs=()
for dir in labs/*/; do [[ -f "$dir/CMakeLists.txt" ]] && labs+=("$(basename "$dir")"); done
set -f  # from here on, words split from the docs are never file name patterns

# Each inline code span of the prose (fenced blocks left out) as FILE<TAB>LINE<TAB>TEXT.
code_spans() {
  awk '
    FNR == 1 { fenced = 0 }
    /^[ \t]*```/ { fenced = !fenced; next }
    fenced { next }
    {
      line = $0
      while (match(line, /`[^`]+`/)) {
        printf "%s\t%d\t%s\n", FILENAME, FNR, substr(line, RSTART + 1, RLENGTH - 2)
        line = substr(line, RSTART + RLENGTH)
      }
    }' "$@"
}

# --- 1. paths in backticks exist -------------------------------------------------------------------
checked=0
path_re='^(framework|labs|tests|tools|resources|docs|cmake|bench)/[^[:space:]]*\.[A-Za-z0-9]+$'
while IFS=$'\t' read -r file line span; do
  for token in $(tr '()[],;="'"'" ' ' <<<"$span"); do
    token="${token#./}"
    token="${token%%:[0-9]*}"      # file.cpp:123
    token="${token%%#*}"           # page.md#anchor
    token="${token%.}"
    [[ "$token" =~ $path_re ]] || continue
    # Placeholders: <lab>, FILE.json, fuzz_TARGET.cpp, NN-topic.md, a glob, an ellipsis.
    [[ "$token" == *[\<\>\*\{\}\$…]* ]] && continue
    base="${token##*/}"
    stem="${base%%.*}"
    [[ "$stem" =~ ^[A-Z][A-Z_-]*$ || "$stem" =~ [_-][A-Z]{3,}$ || "$base" == NN-* ]] && continue
    checked=$((checked + 1))
    [[ -e "$token" ]] && continue
    # The instructor's golden alternatives are left out of the hand-out (tools/student_release.sh).
    [[ -f .student-release && "$token" == tools/golden_alternatives/* ]] && continue
    problem "$file:$line: \`$token\` does not exist"
  done
done < <(code_spans "${docs[@]}")

# --- 2. exercise headings of the workbook: file and function exist -------------------------------
while IFS=$'\t' read -r file line heading; do
  files=() funcs=()
  for span in $(grep -oE '`[^`]+`' <<<"$heading" | tr -d '`'); do
    if [[ "$span" =~ ^[A-Za-z0-9_/]+\.(cpp|h)$ ]]; then files+=("$span")
    elif [[ "$span" =~ ^[A-Za-z_][A-Za-z0-9_]*$ ]]; then funcs+=("$span"); fi
  done
  # A bare file name after the function, as in (`hermiteBasis`, hermite.cpp).
  for bare in $(sed -E 's/`[^`]*`//g' <<<"$heading" | grep -oE '\b[a-z0-9_]+\.(cpp|h)\b'); do files+=("$bare"); done
  paths=()
  for f in "${files[@]}"; do
    if [[ "$f" == */* ]]; then
      if [[ -f "framework/physics/$f" ]]; then paths+=("framework/physics/$f")
      else problem "$file:$line: \`$f\` is not a file under framework/physics/"; fi
    else
      found="$(find framework/physics -name "$f" -type f | head -n 1)"
      if [[ -n "$found" ]]; then paths+=("$found")
      else problem "$file:$line: $f is not a file under framework/physics/"; fi
    fi
  done
  [[ ${#files[@]} -gt 0 && ${#paths[@]} -eq 0 ]] && continue
  [[ ${#paths[@]} -eq 0 ]] && mapfile -t paths < <(find framework/physics -type f \( -name '*.cpp' -o -name '*.h' \))
  for fn in "${funcs[@]}"; do
    grep -qE "\\b$fn[[:space:]]*\\(" "${paths[@]}" ||
      problem "$file:$line: function $fn is not defined in ${files[*]:-framework/physics/}"
  done
done < <(awk '/^###+ [A-Z]+-[0-9]+/ { printf "%s\t%d\t%s\n", FILENAME, FNR, $0 }' "${workbook[@]}")

# --- 3. figures read from the code ---------------------------------------------------------------
guide=docs/instructor-guide.md

# 3a. solution blocks, the way tools/student_release.sh counts them.
blocks_note="solution blocks"
if [[ -f .student-release ]]; then
  blocks_note="solution blocks (not counted: a hand-out has none)"
else
  blocks=0
  while IFS= read -r -d '' f; do
    blocks=$((blocks + $(grep -c '// BEGIN SOLUTION' "$f")))
  done < <(find . \( -path ./.git -o -path ./build -o -path ./tools/golden_alternatives \) -prune -o \
                  -type f \( -name '*.cpp' -o -name '*.h' \) -print0)
  quoted=0
  while IFS=: read -r line n; do
    quoted=1
    [[ "$n" == "$blocks" ]] ||
      problem "$guide:$line: quotes $n solution blocks; the code has $blocks (// BEGIN SOLUTION in .cpp and .h files)"
  done < <(grep -noE '[0-9]+ solution blocks' "$guide" | sed -E 's/ solution blocks//')
  [[ $quoted == 1 ]] || problem "$guide: quotes no count of solution blocks (expected \"$blocks solution blocks\")"
fi

# 3b. packages the driver installs.
packages="$(sed -n '/^PBA_PACKAGES=(/,/)/p' tools/driver_lib.sh | sed -E 's/^PBA_PACKAGES=\(//; s/\).*//; s/#.*//' | wc -w)"
if [[ "$packages" -eq 0 ]]; then
  problem "tools/driver_lib.sh: no PBA_PACKAGES list found"
else
  quoted=0
  while IFS=: read -r file line n; do
    quoted=1
    [[ "$n" == "$packages" ]] ||
      problem "$file:$line: quotes \"packages: all $n installed\"; PBA_PACKAGES in tools/driver_lib.sh has $packages"
  done < <(grep -noE 'packages: all [0-9]+ installed' "${docs[@]}" | sed -E 's/packages: all ([0-9]+) installed/\1/')
  [[ $quoted == 1 || -z "$chapter0" ]] ||
    problem "$chapter0: quotes no \"packages: all N installed\" line (./pba doctor prints it with N = $packages)"
fi

# 3c. the exit code of a run paused by the guard, in every clause that names the guard and an exit code.
guard_code="$(sed -nE 's/.*kExitGuardPaused *= *([0-9]+).*/\1/p' framework/app/lab.h | head -n 1)"
if [[ -z "$guard_code" ]]; then
  problem "framework/app/lab.h: no kExitGuardPaused constant found"
else
  # Prose is joined into paragraphs and split into clauses at ". ", "; ", ", " and ": "; a code block's
  # lines are clauses of their own. Each quote is reported at the line of the paragraph that holds it.
  guard_quotes="$(awk '
    function check(text,   rest, quote, n, at, i) {
      if (tolower(text) !~ /guard/) return
      rest = text
      while (match(rest, /[Ee]xit(s|ed|ing)?( with)?( code| status)? `?[0-9]+/)) {
        quote = substr(rest, RSTART, RLENGTH); n = quote; gsub(/[^0-9]/, "", n)
        at = start
        for (i = 0; i < nlines; i++) if (index(lines[i], quote)) { at = start + i; break }
        printf "%s:%d:%s\n", FILENAME, at, n
        rest = substr(rest, RSTART + RLENGTH)
      }
    }
    function flush(   i, k, parts) {
      if (para == "") return
      k = split(para, parts, /[.;,:] /)
      for (i = 1; i <= k; i++) check(parts[i])
      para = ""; nlines = 0
    }
    FNR == 1 { flush(); fenced = 0 }
    /^[ \t]*```/ { flush(); fenced = !fenced; next }
    fenced { start = FNR; nlines = 1; lines[0] = $0; check($0); nlines = 0; next }
    /^[ \t]*$/ || /^#/ || /^[ \t]*([-*]|[0-9]+\.) / || /^\|/ { flush() }
    { if (para == "") start = FNR; lines[nlines++] = $0; para = para " " $0 }
    END { flush() }' "${docs[@]}")"
  while IFS=: read -r file line n; do
    [[ -z "$file" ]] && continue
    [[ "$n" == "$guard_code" ]] ||
      problem "$file:$line: a run paused by the guard is said to exit $n; kExitGuardPaused in framework/app/lab.h is $guard_code"
  done <<<"$guard_quotes"
  grep -q "^$guide:" <<<"$guard_quotes" ||
    problem "$guide: quotes no exit code for a run paused by the guard (kExitGuardPaused is $guard_code)"
fi

# --- 4. labs that exist are not "not yet written" -----------------------------------------------
while IFS=: read -r file line lab; do
  problem "$file:$line: says the $lab lab is not written yet, but labs/$lab exists"
done < <(for lab in "${labs[@]}"; do
           grep -noE "\\b$lab lab\\b.*(not yet written|not written yet|does not exist yet)" "${docs[@]}" |
             cut -d: -f1,2 | sed "s/\$/:$lab/"
         done)

# --- 5. exercise minutes in the course pages ------------------------------------------------------
catalog=resources/exercises.tsv
if [[ -f "$catalog" ]]; then
  course=()
  for f in "${docs[@]}"; do [[ "$f" == docs/course/* ]] && course+=("$f"); done
  if ! head -n 1 "$catalog" | tr '\t' '\n' | grep -qx minutes; then
    problem "$catalog: no column named minutes in its header"
  elif [[ ${#course[@]} -gt 0 ]]; then
    while IFS= read -r l; do problem "$l"; done < <(awk -F'\t' -v catalog="$catalog" '
      FILENAME == catalog && FNR == 1 { for (i = 1; i <= NF; i++) if ($i == "minutes") col = i; next }
      FILENAME == catalog { if ($1 != "") { minutes[$1] = $col; n++; total += $col } next }
      {
        line = $0
        if (match(line, /\([0-9]+ min\)/)) {
          quoted = substr(line, RSTART + 1, RLENGTH - 6) + 0
          head = substr(line, 1, RSTART - 1)
          sum = 0; tags = ""
          while (match(head, /[A-Z]+-[0-9]+/)) {
            tag = substr(head, RSTART, RLENGTH); head = substr(head, RSTART + RLENGTH)
            if (!(tag in minutes)) { printf "%s:%d: %s is not in %s\n", FILENAME, FNR, tag, catalog; continue }
            sum += minutes[tag]; tags = tags " " tag
          }
          if (tags != "" && sum != quoted)
            printf "%s:%d: quotes %d min for%s; %s gives %d\n", FILENAME, FNR, quoted, tags, catalog, sum
        }
        if (match(line, /All [0-9]+ exercises come to [0-9]+ min/)) {
          split(substr(line, RSTART, RLENGTH), w, " ")
          if (w[2] + 0 != n || w[6] + 0 != total)
            printf "%s:%d: quotes %d exercises and %d min; %s has %d and %d\n", FILENAME, FNR, w[2], w[6], catalog, n, total
        }
        if (FILENAME ~ /syllabus\.md$/ && line ~ /^\| *[0-9]+ *\|/) {
          rest = line
          while (match(rest, /[A-Z]+-[0-9]+/)) { listed[substr(rest, RSTART, RLENGTH)]++; rest = substr(rest, RSTART + RLENGTH) }
          syllabus = FILENAME
        }
      }
      END {
        if (syllabus != "")
          for (tag in minutes)
            if (listed[tag] != 1) printf "%s: the week table lists %s %d times (once expected)\n", syllabus, tag, listed[tag]
      }' "$catalog" "${course[@]}")
  fi
fi

# --- 6. ./pba grade's rows quoted in the docs --------------------------------------------------------
if [[ -f "$catalog" ]]; then
  while IFS= read -r l; do problem "$l"; done < <(awk -F'\t' -v catalog="$catalog" '
    function trim(t) { gsub(/^ +| +$/, "", t); return t }
    FILENAME == catalog && FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    FILENAME == catalog { title[$1] = $col["title"]; minutes[$1] = $col["minutes"]; hint[$1] = $col["hint"]; next }
    FNR == 1 { fenced = 0 }
    /^[ \t]*```/ { fenced = !fenced; next }
    !fenced || !/^[A-Z]+-[0-9]+ / { next }
    {
      tag = $0; sub(/ .*/, "", tag)
      rest = substr($0, length(tag) + 1)
      if (!match(rest, /  +(pass|FAIL)( |$)/)) next
      before = trim(substr(rest, 1, RSTART - 1))
      result = trim(substr(rest, RSTART, RLENGTH))
      shown_hint = trim(substr(rest, RSTART + RLENGTH))
      time = ""
      if (match(before, /  +[0-9]+m$/)) { time = trim(substr(before, RSTART)); before = trim(substr(before, 1, RSTART - 1)) }
      if (!(tag in title)) { printf "%s:%d: grade row for %s, which is not in %s\n", FILENAME, FNR, tag, catalog; next }
      if (before != title[tag])
        printf "%s:%d: grade row for %s shows the title \"%s\"; %s has \"%s\"\n", FILENAME, FNR, tag, before, catalog, title[tag]
      if (time != minutes[tag] "m")
        printf "%s:%d: grade row for %s shows TIME \"%s\"; ./pba grade prints %sm from %s\n", FILENAME, FNR, tag, time, minutes[tag], catalog
      if (result == "FAIL" && shown_hint != hint[tag])
        printf "%s:%d: grade row for %s shows another hint than %s\n", FILENAME, FNR, tag, catalog
    }' "$catalog" "${docs[@]}")
fi

if [[ $problems -gt 0 ]]; then
  echo "check_docs: $problems problem(s): fix the docs (or the figure in the code they quote)"
  exit 1
fi
echo "ok: $checked paths in backticks exist; exercise headings, $blocks_note, package count, the guard's exit code, exercise minutes and grade rows match the code"
