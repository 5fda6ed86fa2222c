#!/usr/bin/env bash
# End-to-end checks of locus-bench: each suite runs on a tiny case with its CSV columns, options
# are validated while the command line is parsed (exit 2), and a failed write is exit 5.
# Usage: tests/bench/bench_test.sh PATH/TO/locus-bench PATH/TO/locus   (from the source root)
set -uo pipefail
bench="$1"
locus="$2"
source "$(dirname "$0")/../cli/expect.sh"

expect "sdf runs and reports the speed-ups" 0 "grid100,101,101,all" -- \
    "$bench" sdf --size 16 --min-seconds 0 --csv
expect "render compares sturm with exact, ray by ray" 0 "sphere,2,sturm,default,0,64," -- \
    "$bench" render --size 8 --cases sphere --methods sturm --surf off --min-seconds 0 --csv
expect "render CSV header names the fastest runs" 0 "render_best_seconds,surf_best_seconds" -- \
    "$bench" render --size 8 --cases sphere --methods sturm --surf off --min-seconds 0 --csv
# The data row: 19 fields, no wrong ray, and without surf its two figures missing (-1) around
# locus' fastest frame.
bench_row=$("$bench" render --size 8 --cases sphere --methods sturm --surf off \
    --min-seconds 0 --csv 2>/dev/null | grep '^sphere,2,sturm,')
if [[ $(head -1 <<<"$bench_row" | awk -F, '{print NF}') != 19 ]] ||
    ! grep -qE '^sphere,2,sturm,default,0,64,[^,]+,[^,]+,[^,]+,0,0,0,.*,-1,[0-9.e+-]+,-1$' <<<"$bench_row"; then
    fail "render CSV row: $bench_row"
else
    echo "ok   render CSV row"; passes=$((passes + 1))
fi
# The PNG writer beside zlib: eight fields, both sizes and all three times positive.
png_row=$("$bench" png --size 32 --cases sphere --min-seconds 0 --csv 2>/dev/null | grep '^sphere,32,')
if [[ $(awk -F, '{print NF}' <<<"$png_row") != 8 ]] ||
    ! awk -F, '{ exit !($3 > 0 && $6 > 0 && $4 > 0 && $7 > 0) }' <<<"$png_row"; then
    fail "png CSV row: $png_row"
else
    echo "ok   png CSV row"; passes=$((passes + 1))
fi
expect "png: an unknown case" 2 "no surface 'nope'" -- "$bench" png --cases nope
expect "groebner times a case without Singular" 0 "cyclic4,\"grevlex\",4," -- \
    "$bench" groebner --cases cyclic4 --singular off --min-seconds 0 --csv
expect "implicit times every route" 0 "sphere,2,4," -- \
    "$bench" implicit --cases sphere --singular off --limit 5 --csv

## Validation while parsing: one message form, exit 2.
expect "render --size 0" 2 "--size: '0': expected N from 1 to 4096" -- "$bench" render --size 0
expect "render --size -1" 2 "--size: '-1'" -- "$bench" render --size -1
expect "render --size 100000" 2 "--size: '100000': expected N from 1 to 4096" -- \
    "$bench" render --size 100000
expect "render --threads -1" 2 "--threads: '-1'" -- "$bench" render --threads -1
expect "groebner --algorithm magic" 2 "'magic': expected auto, buchberger, signature or modular" -- \
    "$bench" groebner --algorithm magic
expect "--min-seconds -1" 2 "--min-seconds: expected seconds from 0 to 3600" -- \
    "$bench" sdf --min-seconds -1
expect "an unknown suite" 2 "" -- "$bench" nosuch
expect "a missing data folder" 2 "SUITE.txt: cannot open (use --data)" -- \
    "$bench" groebner --data /nonexistent --singular off
expect "locus itself has no bench command" 2 "" -- "$locus" bench groebner

if [[ -w /dev/full ]]; then
    expect "render > /dev/full" 5 "cannot write" -- bash -c "\"$bench\" render --size 4 \
        --cases sphere --methods sturm --surf off --min-seconds 0 --csv >/dev/full"
fi
summary
