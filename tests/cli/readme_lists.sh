#!/bin/bash
# The README's lists of names against the program's tables: each `--option a|b|c` list in
# README.md (scenes, engines, projections, pixel formats, displays) must name exactly what
# `noneuclid render --help` / `noneuclid run --help` and `noneuclid scenes` list, in order; and
# docs/file-formats.md's table of the built-in scenes names what `noneuclid scenes` lists.
# Usage: readme_lists.sh NONEUCLID README.md
set -u
prog=$1 readme=$2
fail=0

# The names the help lists under an option: the indented rows below its line.
help_names() {    # COMMAND OPTION
    "$prog" "$1" --help | awk -v opt="  $2 " '
        index($0, opt) == 1 { on = 1; next }
        on && /^      [a-z0-9]/ { print $1; next }
        on && /^  --/ { exit }'
}
# The names the README gives for an option: its `--option a|b|c` (backquoted).
readme_names() {    # OPTION
    grep -o -- "\`$1 [a-z0-9|-]*\`" "$readme" | head -n 1 | sed "s/^\`$1 //; s/\`$//" | tr '|' '\n'
}
check() {    # WHAT EXPECTED ACTUAL
    if [ "$2" != "$3" ]; then
        echo "README.md's $1 differ from the program's: README: $(echo "$3" | paste -sd' ') program: $(echo "$2" | paste -sd' ')"
        fail=1
    else
        echo "$1: $(echo "$2" | paste -sd' ')"
    fi
}
check "engines (--engine)" "$(help_names render --engine)" "$(readme_names --engine)"
check "projections (--projection)" "$(help_names render --projection)" "$(readme_names --projection)"
check "pixel formats (--format)" "$(help_names render --format)" "$(readme_names --format)"
check "displays (--display)" "$(help_names run --display)" "$(readme_names --display)"
check "scenes (noneuclid scenes)" "$("$prog" scenes | awk '{ print $1 }')" "$(readme_names --scene)"
# docs/file-formats.md's table of the built-in scenes: its first column, in order.
formats=$(dirname "$readme")/docs/file-formats.md
check "scenes of docs/file-formats.md's table" "$("$prog" scenes | awk '{ print $1 }')" \
    "$(awk '/^\*\*The built-in scenes:\*\*/ { on = 1; next } on && /^\| `/ { sub(/^\| `/, ""); sub(/`.*/, ""); print; next } on && /^$/ && seen { exit } on && /^\|/ { seen = 1 }' "$formats")"
[ "$(help_names render --engine)" ] || { echo "no engines found in render --help"; fail=1; }
exit $fail
