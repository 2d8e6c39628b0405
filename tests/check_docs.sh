#!/bin/sh
# SPDX-License-Identifier: MIT
# Docs that cannot rot: run by `make test` from the top of the tree.
#
#   sh tests/check_docs.sh DISKS [RENDER [GR [PRESSURE]]]
#
# DISKS, RENDER, GR and PRESSURE are the programs of this build (RENDER is
# skipped with a note when it was not built). Checks, and prints every
# problem as FILE:LINE: what is wrong, exiting 1 if there is any:
#
#  1. every relative link and image in README.md, CHANGELOG.md and
#     docs/*.md resolves to a file, and every #anchor to a heading of the
#     markdown file it points into (GitHub's rule: lowercase, punctuation
#     dropped, spaces to '-', a repeated heading gets -1, -2, ...);
#  2. every option that `PROGRAM --help` prints is in the program's manual
#     page (the .TP tags of OPTIONS) and in the options table of its docs
#     page (between "<!-- options: NAME" and "<!-- end options -->"), and
#     neither documents an option the help does not print: disks, the
#     renderer, the analysis programs (man/disks-gr.1 ...) and the sweeps
#     of tools/analysis/ (man/disks-eos.1 ..., docs/sweeps.md);
#  3. every option in an example command (code blocks and inline code of
#     the markdown pages, EXAMPLES of the manual pages) is one the program
#     has;
#  4. the README's library example is examples/minimal.c (after its
#     opening comment), as the README says, its compile lines name files
#     that exist, and every "man ./man/PAGE" of the pages names a page;
#  5. man/disk_sim.3 and docs/library.md name every function of the
#     public headers (include/disk_sim.h and include/disksim/*.h), and no
#     page names a ds_ or DS_ identifier that the sources do not define or
#     use (CHANGELOG.md may name the 2.x names that
#     tools/migrate/disksim3.py renames);
#  6. the manual pages render without a groff warning and carry the
#     header's version in their .TH line.
#
# The lists of files below are split into words on purpose (no file of the
# tree has a space in its name).
# shellcheck disable=SC2086
set -u
export LC_ALL=C

# A program path without a slash is run from here, not looked up on PATH.
here() { case $1 in */* | '') echo "$1" ;; *) echo "./$1" ;; esac; }
disks=$(here "${1:?usage: check_docs.sh DISKS [RENDER [GR [PRESSURE [TRANSPORT [RHEOLOGY]]]]]}")
render=$(here "${2:-}")
gr=$(here "${3:-}")
pressure=$(here "${4:-}")
transport=$(here "${5:-}")
rheology=$(here "${6:-}")

MD_FILES="README.md CHANGELOG.md $(ls docs/*.md)"
MAN_FILES=$(ls man/*.[0-9])
HEADERS="include/disk_sim.h $(ls include/disksim/*.h)"
VERSION_HEADER=include/disksim/base.h

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
problems=0
problem() { echo "check_docs: $*" >&2; problems=$((problems + 1)); }
note() { echo "check_docs: $*"; }

# ------------------------------------------------------------ 1. links

# The anchors GitHub makes for the headings of a markdown file, one a line.
anchors() {
    awk '
    /^(```|~~~)/ { fence = !fence; next }
    fence { next }
    {
        line = $0
        while (match(line, /<a (id|name)="[^"]*"/)) {
            a = substr(line, RSTART, RLENGTH); sub(/^<a (id|name)="/, "", a); sub(/"$/, "", a)
            print a; line = substr(line, RSTART + RLENGTH)
        }
    }
    /^#+ / {
        h = $0
        sub(/^#+ +/, "", h); sub(/ +#+ *$/, "", h)
        while (match(h, /!?\[[^]]*\]\([^)]*\)/)) {          # a link: its text
            t = substr(h, RSTART, RLENGTH); sub(/^!?\[/, "", t); sub(/\]\(.*$/, "", t)
            h = substr(h, 1, RSTART - 1) t substr(h, RSTART + RLENGTH)
        }
        h = tolower(h)
        out = ""
        for (i = 1; i <= length(h); ++i) {
            c = substr(h, i, 1)
            if (c ~ /[a-z0-9_-]/ || c > "~") out = out c
            else if (c == " ") out = out "-"
        }
        n = seen[out]++
        print (n ? out "-" n : out)
    }' "$1"
}

# FILE LINE TARGET for every link, image and reference definition outside
# code blocks and inline code.
links() {
    awk '
    /^(```|~~~)/ { fence = !fence; next }
    fence { next }
    {
        line = $0
        gsub(/`[^`]*`/, "", line)
        if (match(line, /^ *\[[^]]+\]: */)) {
            t = substr(line, RLENGTH + 1); sub(/ .*/, "", t); print FILENAME, FNR, t
            next
        }
        while (match(line, /\]\([^)]*\)/)) {
            t = substr(line, RSTART + 2, RLENGTH - 3); line = substr(line, RSTART + RLENGTH)
            sub(/^ *</, "", t); sub(/>.*$/, "", t); sub(/ .*$/, "", t)
            print FILENAME, FNR, t
        }
        while (match(line, /(src|href)="[^"]*"/)) {
            t = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
            sub(/^[a-z]*="/, "", t); sub(/"$/, "", t)
            print FILENAME, FNR, t
        }
    }' "$@"
}

links $MD_FILES > "$work/links"
nlinks=0
while read -r file line target; do
    nlinks=$((nlinks + 1))
    case $target in
    '') problem "$file:$line: empty link"; continue ;;
    [a-zA-Z]*:*) continue ;; # http:, https:, mailto: ...
    esac
    path=${target%%#*}
    anchor=
    case $target in *'#'*) anchor=${target#*#} ;; esac
    if [ -z "$path" ]; then
        resolved=$file
    else
        resolved=$(dirname "$file")/$path
    fi
    if [ ! -e "$resolved" ]; then
        problem "$file:$line: link to $target: no file $resolved"
        continue
    fi
    if [ -n "$anchor" ]; then
        case $resolved in
        *.md)
            anchors "$resolved" | grep -qxF -- "$anchor" ||
                problem "$file:$line: link to $target: $resolved has no heading with anchor #$anchor"
            ;;
        *) problem "$file:$line: link to $target: an anchor into a file that is not markdown" ;;
        esac
    fi
done < "$work/links"
note "$nlinks links in $(echo $MD_FILES | wc -w) markdown files checked"

# ------------------------------------------------------------ 2. options

# The option words of a text: -x and --name after a space, '(', '[', ',',
# a backtick or the line start; --name=VALUE gives --name.
option_words() {
    awk '{
        line = $0
        while (match(line, /(^|[[ \t,(`"])--?[a-z][a-z0-9-]*/)) {
            w = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
            sub(/^[^-]*/, "", w); sub(/-+$/, "", w)
            print w
        }
    }' | sort -u
}

help_options() { "$1" --help 2>&1 | option_words; }

# The options named in the .TP tags of a manual page's OPTIONS section.
man_options() {
    awk '
    /^\.SH / { on = ($0 ~ /^\.SH "?OPTIONS"?$/); next }
    on && /^\.TP/ { tag = 1; next }
    on && tag { tag = 0; gsub(/\\-/, "-"); gsub(/\\f[BIRP]/, ""); print }
    ' "$1" | option_words
}

# The options in the first column of the table between the markers, or
# the line --no-options-table if the file has no such table.
md_options() {
    if ! grep -q "^<!-- options: $2 " "$1"; then
        echo --no-options-table
        return
    fi
    awk -v name="$2" '
    index($0, "<!-- options: " name " ") == 1 { on = 1; next }
    on && index($0, "<!-- end options -->") == 1 { on = 0; next }
    on && /^\|/ { line = $0; gsub(/\\\|/, "/", line); split(line, cell, "|"); print cell[2] }
    ' "$1" | option_words
}

# compare NAME HELPFILE DOCFILE WHERE: both directions.
# (Shell functions share their variables: each function here has its own.)
compare_options() {
    co_name=$1 co_help=$2 co_doc=$3 co_where=$4
    if grep -qx -- --no-options-table "$co_doc"; then
        problem "$co_where: no options table for $co_name (<!-- options: $co_name ... --> ... <!-- end options -->)"
        return
    fi
    for o in $(comm -23 "$co_help" "$co_doc"); do
        problem "$co_where: $co_name --help has $o, which is not documented here"
    done
    for o in $(comm -13 "$co_help" "$co_doc"); do
        problem "$co_where: documents $o, which $co_name --help does not have"
    done
}

# check_program NAME BINARY MANPAGE|- DOC TABLE
check_program() {
    cp_name=$1 cp_bin=$2 cp_page=$3 cp_doc=$4 cp_table=$5
    help_options "$cp_bin" > "$work/help_$cp_name"
    if [ ! -s "$work/help_$cp_name" ]; then
        problem "$cp_bin --help printed no options"
        return 1
    fi
    cp_where=$cp_doc
    if [ "$cp_page" != - ]; then
        man_options "$cp_page" > "$work/man_$cp_name"
        compare_options "$cp_name" "$work/help_$cp_name" "$work/man_$cp_name" "$cp_page OPTIONS"
        cp_where="$cp_page and $cp_doc"
    fi
    md_options "$cp_doc" "$cp_table" > "$work/md_$cp_name"
    compare_options "$cp_name" "$work/help_$cp_name" "$work/md_$cp_name" \
        "$cp_doc (options table '$cp_table')"
    note "$cp_name: $(wc -l < "$work/help_$cp_name") options of --help compared with $cp_where"
}

checked_programs=
check_program disks "$disks" man/disks.1 docs/cli.md disks && checked_programs=" disks"
if [ -n "$render" ] && [ -x "$render" ]; then
    check_program render "$render" man/disks-render.1 docs/rendering.md render &&
        checked_programs="$checked_programs render"
else
    note "renderer not built: its options are not checked (${render:-no path given})"
fi
if [ -n "$gr" ] && [ -x "$gr" ]; then
    check_program gr "$gr" man/disks-gr.1 docs/cli.md gr && checked_programs="$checked_programs gr"
fi
if [ -n "$pressure" ] && [ -x "$pressure" ]; then
    check_program pressure "$pressure" man/disks-pressure.1 docs/cli.md pressure &&
        checked_programs="$checked_programs pressure"
fi
if [ -n "$transport" ] && [ -x "$transport" ]; then
    check_program transport "$transport" man/disks-transport.1 docs/cli.md transport &&
        checked_programs="$checked_programs transport"
fi
if [ -n "$rheology" ] && [ -x "$rheology" ]; then
    check_program rheology "$rheology" man/disks-rheology.1 docs/cli.md rheology &&
        checked_programs="$checked_programs rheology"
fi
# The sweeps installed as disks-eos, disks-eos-slurm, disks-diffusion and
# disks-jamming: their help against their man pages and docs/sweeps.md
# (disks-eos-slurm shares the page of disks-eos, whose OPTIONS are eos's).
for sweep in eos:eos.sh:man/disks-eos.1 eos-slurm:eos.sbatch:- \
             diffusion:diffusion_sweep.sh:man/disks-diffusion.1 jamming:jamming.sh:man/disks-jamming.1; do
    sw_name=${sweep%%:*} sw_rest=${sweep#*:}
    check_program "$sw_name" "tools/analysis/${sw_rest%%:*}" "${sw_rest#*:}" docs/sweeps.md "$sw_name" &&
        checked_programs="$checked_programs $sw_name"
done

# ------------------------------------------------------------ 3. example commands

# FILE LINE PROGRAM OPTION for every option in a command line of a code
# block or inline code (markdown) or of EXAMPLES (manual pages). Lines
# ending in a backslash continue; a command ends at | ; && > ) # or the
# end of the code. The generated bad-input table is left out: its
# commands are wrong on purpose.
command_lines() {
    awk '
    FNR == 1 { fence = 0; table = 0; ex = 0; held = "" }
    function commands(text, where,    w, rest, seg, prog) {
        while (match(text, /(^|[ \/;&|(`$])(disks-render|disks-gr|disks-pressure|disks-transport|disks-rheology|disks-eos-slurm|disks-eos|disks-diffusion|disks-jamming|disks|render-osmesa|render-egl|render|gr|pressure|transport|rheology|eos\.sh|eos\.sbatch|diffusion_sweep\.sh|jamming\.sh)( |$)/)) {
            w = substr(text, RSTART, RLENGTH); rest = substr(text, RSTART + RLENGTH)
            sub(/^[ \/;&|(`$]/, "", w); sub(/ $/, "", w)
            prog = w
            if (prog ~ /render/) prog = "render"
            # The installed names of the analysis commands, and the sweeps
            # by their names in the tree.
            if (prog ~ /^disks-./) sub(/^disks-/, "", prog)
            if (prog == "eos.sh") prog = "eos"
            if (prog == "eos.sbatch") prog = "eos-slurm"
            if (prog == "diffusion_sweep.sh") prog = "diffusion"
            if (prog == "jamming.sh") prog = "jamming"
            seg = rest
            sub(/(\||;|&&|>|\)|#|`).*$/, "", seg)
            printf "%s %s %s %s\n", FILENAME, where, prog, seg
            text = rest
        }
    }
    FILENAME ~ /\.[0-9]$/ {
        if ($0 ~ /^\.SH /) { ex = ($0 ~ /EXAMPLES/); next }
        if (!ex) next
        if ($0 ~ /^\.EX/) { code = 1; next }
        if ($0 ~ /^\.EE/) { code = 0; next }
        if (!code) next
        line = $0
        gsub(/\\-/, "-", line); gsub(/\\\(aq/, "\047", line); gsub(/\\e/, "\\", line)
        if (line ~ /\\$/) { held = held substr(line, 1, length(line) - 1) " "; next }
        commands(held line, FNR); held = ""
        next
    }
    /^(```|~~~)/ { fence = !fence; held = ""; next }
    index($0, "<!-- bad-input-table:") == 1 { table = 1; next }
    index($0, "<!-- end bad-input-table -->") == 1 { table = 0; next }
    table { next }
    fence {
        line = $0
        if (line ~ /\\$/) { held = held substr(line, 1, length(line) - 1) " "; next }
        commands(held line, FNR); held = ""
        next
    }
    {
        line = $0
        while (match(line, /`[^`]+`/)) {
            code = substr(line, RSTART + 1, RLENGTH - 2)
            line = substr(line, RSTART + RLENGTH)   # before commands() moves RSTART
            commands(code, FNR)
        }
    }' "$@"
}

command_lines $MD_FILES $MAN_FILES > "$work/commands"
ncommands=0
while read -r file line prog args; do
    case " $checked_programs " in *" $prog "*) ;; *) continue ;; esac
    ncommands=$((ncommands + 1))
    for o in $(printf '%s\n' " $args" | option_words); do
        grep -qxF -- "$o" "$work/help_$prog" ||
            problem "$file:$line: example command '$prog$([ -n "$args" ] && printf ' %s' "$args")' uses $o, which $prog does not have"
    done
done < "$work/commands"
note "$ncommands example commands of${checked_programs:- no program} checked"

# ------------------------------------------------------------ 4. README example

awk '/^## Use the library/ { on = 1; next } /^## / { on = 0 }
     on && /^```c/ { code = 1; next } code && /^```/ { exit } code' README.md > "$work/readme.c"
if [ ! -s "$work/readme.c" ]; then
    problem "README.md: no C example under \"## Use the library\""
else
    # examples/minimal.c from its first line that is not in the comments
    # (a licence line, the opening comment) and blank lines that open it.
    awk 'lead && c { if (/\*\//) c = 0; next }
         lead && (/^[ \t]*$/ || /^[ \t]*\/\//) { next }
         lead && /^[ \t]*\/\*/ { if (!/\*\//) c = 1; next }
         { lead = 0; print }' lead=1 examples/minimal.c > "$work/minimal.c"
    cmp -s "$work/readme.c" "$work/minimal.c" ||
        problem "README.md: the library example differs from examples/minimal.c: $(diff "$work/minimal.c" "$work/readme.c" | head -3 | tr '\n' ' ')"
fi

# The C files the README's compile lines name, and the manual pages the
# pages read by path ("man ./man/disks.1"), exist from the top of the tree,
# where the README says to run them.
awk '/^```/ { fence = !fence; next }
     { line = $0
       while (match(line, /(^|[ `])cc [^`]*[.]c/)) {
           c = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
           n = split(c, w, " "); print FNR, w[n]
       } }' README.md > "$work/compiled"
while read -r line file; do
    [ -f "$file" ] || problem "README.md:$line: a compile line names $file, which is not in the tree"
done < "$work/compiled"
grep -no 'man \./man/[A-Za-z0-9_.-]*' $MD_FILES | while IFS=: read -r file line cmd; do
    [ -f "${cmd#man }" ] || echo "$file:$line: '$cmd': no page ${cmd#man ./}"
done > "$work/pages"
while read -r what; do problem "$what"; done < "$work/pages"

# ------------------------------------------------------------ 5. the API named

sed -n '/^[a-z]/s/^[^(]*[ *]\(ds_[a-z0-9_]*\)(.*/\1/p' $HEADERS | sort -u > "$work/functions"
for page in man/disk_sim.3 docs/library.md; do
    grep -o 'ds_[a-z0-9_]*' "$page" | sort -u > "$work/named"
    for f in $(comm -23 "$work/functions" "$work/named"); do
        problem "$page: does not name $f, which the public headers declare"
    done
done
# Every identifier the code defines or uses: the C and shell files of the
# tree, wherever they are (sources, command, tools, tests, examples).
find . \( -name .git -o -name 'build*' \) -prune -o -type f \( -name '*.[ch]' -o -name '*.sh' \) \
    -exec grep -oh '\(ds\|DS\)_[A-Za-z0-9_]*' {} + | sort -u > "$work/identifiers"
awk '{
    line = $0
    while (match(line, /(ds|DS)_[A-Za-z0-9_]*[*]?/)) {
        w = substr(line, RSTART, RLENGTH); before = RSTART > 1 ? substr(line, RSTART - 1, 1) : ""
        line = substr(line, RSTART + RLENGTH)
        if (before ~ /[A-Za-z0-9_]/) continue      # inside another word (libdisksim_...)
        print FILENAME, FNR, w
    }
}' $MD_FILES $MAN_FILES > "$work/mentions"
# The 2.x names, which only the changelog's history and table may name.
grep -oh '\(ds\|DS\)_[A-Za-z0-9_]*' tools/migrate/disksim3.py | sort -u > "$work/old_names"
while read -r file line w; do
    if [ "$file" = CHANGELOG.md ] && grep -qxF "${w%\*}" "$work/old_names"; then
        continue
    fi
    case $w in
    *_\*) grep -q "^${w%\*}" "$work/identifiers" ||
              problem "$file:$line: $w matches no identifier of the sources" ;;
    *\*) grep -qxF "${w%\*}" "$work/identifiers" ||
              problem "$file:$line: ${w%\*} is no identifier of the sources" ;;
    *_) ;; # a prefix in prose ("ds_")
    *) grep -qxF "$w" "$work/identifiers" ||
           problem "$file:$line: $w is no identifier of the sources" ;;
    esac
done < "$work/mentions"

# ------------------------------------------------------------ 6. manual pages

version=$(sed -n 's/^#define DS_VERSION_STRING "\(.*\)"/\1/p' "$VERSION_HEADER")
for page in $MAN_FILES; do
    grep -q "^\.TH .* \"disksim $version\"" "$page" ||
        problem "$page: the .TH line does not name disksim $version"
done
if command -v groff >/dev/null 2>&1; then
    for page in $MAN_FILES; do
        out=$(groff -man -Tutf8 -ww -z "$page" 2>&1)
        [ -z "$out" ] || problem "$page: groff warnings: $out"
    done
else
    note "groff is not installed (Debian: groff-base): the manual pages' rendering is not checked"
fi

# ------------------------------------------------------------ 7. the licence

# Every file of the tree that holds code or a manual says its licence in
# an SPDX line near its top (after a #! line).
if command -v git >/dev/null 2>&1 && git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    licensed=0
    for f in $(git ls-files '*.c' '*.h' '*.sh' '*.plt' '*.py' '*.1' '*.3' Makefile .ci/run \
               disksim.pc.in); do
        [ -f "$f" ] || continue
        if head -n 3 "$f" | grep -q 'SPDX-License-Identifier: MIT'; then
            licensed=$((licensed + 1))
        else
            problem "$f: no 'SPDX-License-Identifier: MIT' line at its top"
        fi
    done
    echo "check_docs: $licensed source files carry the licence's SPDX line"
else
    note "not a git checkout: the SPDX lines are not checked"
fi

if [ "$problems" -ne 0 ]; then
    echo "check_docs: $problems problems" >&2
    exit 1
fi
echo "check_docs: links, options, example commands, the README example, the API, the manual pages and the licence lines: OK"
