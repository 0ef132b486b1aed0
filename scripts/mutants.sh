#!/usr/bin/env bash
# The project's mutation run (issue 24): applies each one-line mutant of tests/mutants/mutants.txt
# to the source, one at a time, rebuilds incrementally, runs the tests that cover its folder (the
# whole suite to confirm a survivor), restores the file and prints the kill rate and the survivors.
# A kill must repeat: a failing test is run up to three times (ctest --repeat until-pass:3), and a
# mutant whose failing tests all pass on a repeat survives (a flaky test under load kills nothing).
# Not part of CI (an hour on two cores). Run it on a tree whose tests pass, with build/ configured
# (scripts/build.sh).
#
#   scripts/mutants.sh [--list FILE] [--only REGEX] [--timeout SECONDS] [--no-confirm] [--check]
#
# --check only checks every entry (its text found once, its regex matching tests) and exits;
# --only runs the mutants whose name (the comment line above the entry) matches REGEX;
# --no-confirm counts a mutant its covering tests miss as a survivor without running the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
list=tests/mutants/mutants.txt
only=""
timeout=300
confirm=1
check=0
build=build
while [ $# -gt 0 ]; do
    case "$1" in
        --list) list=$2; shift 2 ;;
        --only) only=$2; shift 2 ;;
        --timeout) timeout=$2; shift 2 ;;
        --no-confirm) confirm=0; shift ;;
        --check) check=1; shift ;;
        *) echo "usage: $0 [--list FILE] [--only REGEX] [--timeout SECONDS] [--no-confirm] [--check]" >&2; exit 2 ;;
    esac
done
[ -f "$build/CMakeCache.txt" ] || { echo "no $build/: run scripts/build.sh first" >&2; exit 2; }

# ---- the list: entries of "file:", "from:", "to:", "tests:" lines, each named by the comment above it
names=() files=() froms=() tos=() regexes=()
name="" file="" from="" to="" tests=""
flush() {
    if [ -n "$file$from$to$tests" ]; then
        if [ -z "$file" ] || [ -z "$from" ] || [ -z "$tests" ]; then
            echo "$list: the entry '$name' needs file:, from:, to: and tests:" >&2; exit 2
        fi
        names+=("$name") files+=("$file") froms+=("$from") tos+=("$to") regexes+=("$tests")
    fi
    name="" file="" from="" to="" tests=""
}
while IFS= read -r line || [ -n "$line" ]; do
    case "$line" in
        "") flush ;;
        "#"*) [ -z "$file$from" ] && name=$(sed -E 's/^#+ *//' <<<"$line") ;;
        file:*) file=$(sed -E 's/^file: *//' <<<"$line") ;;
        from:*) from=$(sed -E 's/^from: *//' <<<"$line") ;;
        to:*) to=$(sed -E 's/^to: *//' <<<"$line") ;;
        tests:*) tests=$(sed -E 's/^tests: *//' <<<"$line") ;;
        *) echo "$list: cannot read the line '$line'" >&2; exit 2 ;;
    esac
done <"$list"
flush

# Occurrences of the text $2 in file $1 (Perl: exact text, no pattern).
occurrences() { FROM=$2 perl -0777 -ne '$n = () = /\Q$ENV{FROM}\E/g; print $n' "$1"; }
# Replaces the one occurrence of $2 in file $1 by $3.
replace_once() { FROM=$2 TO=$3 perl -0777 -pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$1"; }

# The original of the mutated file waits in the build folder, so that a run killed outright
# (SIGKILL) is undone by the next one.
saved=$build/mutant-original
restore() {
    if [ -f "$saved/path" ]; then
        cp "$saved/file" "$(cat "$saved/path")"
        rm -rf "$saved"
    fi
}
if [ -f "$saved/path" ]; then
    echo "restoring $(cat "$saved/path"), left mutated by an earlier run"
    restore
fi

# ---- every entry is checked before anything is changed: a stale entry fails loudly
selected=()
bad=0
for i in "${!names[@]}"; do
    [ -n "$only" ] && ! grep -Eq -- "$only" <<<"${names[$i]}" && continue
    selected+=("$i")
    f=${files[$i]}
    if [ ! -f "$f" ]; then
        echo "mutant '${names[$i]}': no file $f" >&2; bad=1; continue
    fi
    n=$(occurrences "$f" "${froms[$i]}")
    if [ "$n" != 1 ]; then
        echo "mutant '${names[$i]}': '${froms[$i]}' occurs $n times in $f (must be exactly once)" >&2; bad=1
    fi
    if ! ctest --test-dir "$build" -N -R "${regexes[$i]}" | grep -q "Total Tests: [1-9]"; then
        echo "mutant '${names[$i]}': no test matches '${regexes[$i]}'" >&2; bad=1
    fi
done
[ "$bad" = 0 ] || exit 2
[ "${#selected[@]}" -gt 0 ] || { echo "no mutant matches '$only'" >&2; exit 2; }
if [ "$check" = 1 ]; then
    echo "${#selected[@]} mutants checked"
    exit 0
fi

# ---- the covering tests must pass on the unmutated tree, or every mutant would look killed
cmake --build "$build" -j2 >/dev/null
mapfile -t covering < <(for i in "${selected[@]}"; do echo "${regexes[$i]}"; done | sort -u)
echo "baseline: ${#covering[@]} covering test sets on the unmutated tree"
for regex in "${covering[@]}"; do
    ctest --test-dir "$build" -R "$regex" -j2 --timeout "$timeout" >/dev/null 2>&1 ||
        { echo "the tests '$regex' fail on the unmutated tree: fix them first" >&2; exit 1; }
done

# ---- one mutant at a time; the file is restored whatever happens
work=$(mktemp -d)
finish() {
    restore
    rm -rf "$work"
}
trap finish EXIT
trap 'echo "interrupted: the source is restored; rebuild with scripts/build.sh" >&2; exit 130' INT TERM

log=$work/log
killed=0 survived=0 stillborn=0
survivors=() nocompile=()
echo "mutation run: ${#selected[@]} mutants from $list"
for i in "${selected[@]}"; do
    f=${files[$i]}
    mkdir -p "$saved"
    cp "$f" "$saved/file"
    echo "$f" >"$saved/path"
    replace_once "$f" "${froms[$i]}" "${tos[$i]}"
    start=$SECONDS
    if ! cmake --build "$build" -j2 >"$log" 2>&1; then
        outcome="does not compile"
        stillborn=$((stillborn + 1)); nocompile+=("${names[$i]}")
    elif ! ctest --test-dir "$build" -R "${regexes[$i]}" -j2 --timeout "$timeout" --repeat until-pass:3 >"$log" 2>&1; then
        outcome="killed"
        killed=$((killed + 1))
    elif [ "$confirm" = 1 ] && ! ctest --test-dir "$build" -j2 --timeout "$timeout" --repeat until-pass:3 >"$log" 2>&1; then
        outcome="killed by the whole suite (not by '${regexes[$i]}')"
        killed=$((killed + 1))
    else
        outcome="SURVIVED"
        survived=$((survived + 1)); survivors+=("${names[$i]} ($f)")
    fi
    restore
    printf '%3d/%d %-9s %4ds  %s: %s\n' "$((killed + survived + stillborn))" "${#selected[@]}" \
        "${outcome%% *}" "$((SECONDS - start))" "${names[$i]}" "$outcome"
done
cmake --build "$build" -j2 >"$log" 2>&1 || { cat "$log"; echo "the restored tree does not build" >&2; exit 1; }

scored=$((killed + survived))
echo
echo "killed $killed of $scored mutants: $(awk -v k="$killed" -v n="$scored" 'BEGIN { printf "%.1f%%", n ? 100 * k / n : 0 }')"
[ "$stillborn" = 0 ] || printf 'not compiling (not scored; fix the entry):\n%s\n' "$(printf '  %s\n' "${nocompile[@]}")"
if [ "$survived" -gt 0 ]; then
    echo "survivors:"
    printf '  %s\n' "${survivors[@]}"
fi
