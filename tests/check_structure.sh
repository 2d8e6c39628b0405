#!/bin/sh
# SPDX-License-Identifier: MIT
# The structure docs/architecture.md promises, checked from the code:
#  1. no two files of the library call each other, directly or round a
#     circle (from the objects' symbols: file A calls file B when A uses a
#     symbol B defines);
#  2. no source file of the library or the command above 500 lines;
#  3. no function above 80 lines, unless the comment above it says why
#     with a line "Long: ..." (the reason).
# Usage: tests/check_structure.sh BUILD_DIR (the objects of build/).
set -u
build=${1:-build}
fail=0

# 1. Circles. Every library object's defined and undefined symbols.
# The library's folders (src/*/ built into BUILD/*/), then the command's.
objs=$(for d in src/*/; do d=${d#src/}; ls "$build/${d%/}"/*.o 2>/dev/null; done | sort)
if [ -z "$objs" ]; then
    echo "check_structure: no objects under $build (run make first)"
    exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for o in $objs; do
    f=${o#"$build"/}
    nm --defined-only -g "$o" | awk -v f="$f" 'NF == 3 { print $3, f }' >>"$tmp/defs"
    nm -u "$o" | awk -v f="$f" '{ print $2, f }' >>"$tmp/uses"
done
# Edges "user definer", each once.
awk 'NR == FNR { def[$1] = $2; next } ($1 in def) && def[$1] != $2 { print $2, def[$1] }' \
    "$tmp/defs" "$tmp/uses" | sort -u >"$tmp/edges"
# A circle is a file that can reach itself: Floyd-Warshall over the files.
circles=$(awk '
    { a[$1] = 1; a[$2] = 1; e[$1 SUBSEP $2] = 1 }
    END {
        n = 0
        for (f in a) name[n++] = f
        for (k = 0; k < n; ++k) for (i = 0; i < n; ++i) if (e[name[i] SUBSEP name[k]])
            for (j = 0; j < n; ++j) if (e[name[k] SUBSEP name[j]]) e[name[i] SUBSEP name[j]] = 1
        for (i = 0; i < n; ++i) if (e[name[i] SUBSEP name[i]]) {
            line = name[i] ":"
            for (j = 0; j < n; ++j)
                if (j != i && e[name[i] SUBSEP name[j]] && e[name[j] SUBSEP name[i]]) line = line " " name[j]
            print line
        }
    }' "$tmp/edges" | sort)
if [ -n "$circles" ]; then
    echo "check_structure: files that call each other (each with the files of its circle):"
    echo "$circles" | sed 's/^/  /'
    fail=1
fi

# 2. and 3. Lengths of files and functions (clang-format layout: a
# function's body opens with "{" alone at column 0 and closes with "}").
for f in $(find src cli -name '*.[ch]' | sort); do
    lines=$(wc -l <"$f")
    if [ "$lines" -gt 500 ]; then
        echo "check_structure: $f has $lines lines (at most 500: two concepts?)"
        fail=1
    fi
    awk -v f="$f" '
        /^\/\*/ { comment = ""; in_comment = 1 }
        in_comment { comment = comment $0 "\n"; if ($0 ~ /\*\//) in_comment = 0; next }
        /^[A-Za-z].*\(/ && !/;$/ { head = $0; head_line = NR; why = (comment ~ /Long: /) }
        /^\{$/ { start = NR }
        /^\}/ && start {
            len = NR - start - 1
            if (len > 80 && !why)
                printf "check_structure: %s:%d: %s is %d lines (at most 80, or a comment \"Long: why\")\n", f, head_line, head, len
            start = 0; comment = ""
        }
        /^$/ && !start { comment = "" }
    ' "$f" >>"$tmp/long"
done
if [ -s "$tmp/long" ]; then
    cat "$tmp/long"
    fail=1
fi
[ "$fail" -eq 0 ] && echo "check_structure: no circles, files within 500 lines, functions within 80"
exit "$fail"
