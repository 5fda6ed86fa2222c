#!/usr/bin/env bash
# Hostile input, faults and limits: every case ends with a one-line error and the exit
# code of the table in `locus --help` (0 ok, 1 a "no", 2 bad input, 3 timeout, 4 verification
# failed, 5 resource limit, 70 a bug), never a crash, a hang or a truncated file.
# Usage: tests/cli/hostile_input_test.sh PATH/TO/locus [sanitized]   (from the source root)
# With "sanitized" (the debug preset) the wall-clock bounds are relaxed and --max-memory, which
# cannot work under AddressSanitizer's reserved shadow memory, is not tried.
set -uo pipefail
locus="$1"
sanitized="${2:-}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/expect.sh"

# A --timeout of T seconds must end the process within 1.1 T + 0.2 s (the issue's bound) plus
# 0.8 s for start-up and a loaded machine; the sanitized build starts slower.
slack=0.8
[[ -n "$sanitized" ]] && slack=10
deadline() { awk -v t="$1" -v s="$slack" 'BEGIN { print 1.1 * t + 0.2 + s }'; }
# Refusals that must come before the work (which would take minutes): 2 s, or 10 s for the
# sanitized build's start-up.
before_work=2
[[ -n "$sanitized" ]] && before_work=10

# lacks NAME PATTERN -- COMMAND...: the output must not contain PATTERN (any exit code).
lacks() {
    local name="$1" pattern="$2"
    shift 3
    if "$@" 2>&1 | grep -qF -- "$pattern"; then
        fail "$name: output contains '$pattern'"
    else
        echo "ok   $name"; passes=$((passes + 1))
    fi
}
repeat() { awk -v n="$1" -v s="$2" 'BEGIN { for (i = 0; i < n; ++i) printf "%s", s }'; }

sphere="x^2+y^2+z^2-1"
cyclic=tests/data/known/cyclic4_grevlex.ideal

## 1. Deep nesting: a bounded parser in every place that reads polynomials.
parens="$(repeat 10000 '(')x$(repeat 10000 ')')"
printf 'vars: x\n%s\n' "$parens" >"$tmp/deep.ideal"
expect "deep parentheses in an ideal file" 2 "line 2, column 257: expected parentheses nested at most 256 deep" -- \
    "$locus" groebner "$tmp/deep.ideal"
expect "deep parentheses on the command line" 2 "nested at most 256 deep" -- \
    bash -c "echo '0 0 5 0 0 -1' | \"$locus\" trace '$parens'"
printf 'params: u\nx = %s\ny = u^2\nz = u^3\n' "${parens//x/u}" >"$tmp/deep.param"
expect "deep parentheses in a .param file" 2 "line 2, column 261: expected parentheses nested" -- \
    "$locus" implicitize "$tmp/deep.param"
# At the limit a .param still parses, also in the sanitized build (1000 levels overflowed its
# stack there).
printf 'params: u\nx = %su%s\ny = u^2\nz = u^3\n' "$(repeat 256 '(')" "$(repeat 256 ')')" \
    >"$tmp/limit.param"
expect "256 nested parentheses in a .param parse" 0 "verified" -- "$locus" implicitize "$tmp/limit.param"
printf '[[surface]]\nequation = "%s"\n' "$parens" >"$tmp/deep.toml"
expect "deep parentheses in a TOML equation" 2 "deep.toml: line 2, column 12: surface[1].equation: line 1, column 257" -- \
    "$locus" render "$tmp/deep.toml" -o "$tmp/deep.png"
expect "deep parentheses in ideal member's polynomial" 2 "nested at most 256 deep" -- \
    "$locus" ideal member "$cyclic" "$(repeat 5000 '(')x0$(repeat 5000 ')')"
printf 'vars: x\n%sx\n' "$(repeat 20000 '-')" >"$tmp/minus.ideal"
expect "20 000 unary minuses parse (iteratively)" 0 "x" -- "$locus" groebner "$tmp/minus.ideal"

## 2. --timeout in every phase: reading, parsing, expansion, algorithms, output.
# Random inputs from awk with a generator of its own (Park–Miller: exact in doubles, so the same
# numbers in mawk and gawk, whose rand() differ). No generator has a constant term: the ideals
# are not the unit ideal, which the auto route would find at once; the jobs take minutes.
random_awk='function next_random(n) { state = (state * 16807) % 2147483647; return state % n }'
awk "$random_awk"' BEGIN { state = 7; print "vars: x,y,z"
    for (i = 0; i < 200000; ++i)
        printf "%d*x^%d*y^%d+%d*z^%d-%d*x*y^%d\n", 1 + next_random(99), 1 + next_random(8),
            next_random(9), 1 + next_random(99), 1 + next_random(8), 1 + next_random(999),
            next_random(9) }' >"$tmp/many.ideal"
# The signature algorithm finds these 200 000 generators' ideal, (x, z), in a fraction of a
# second (the modular algorithm takes minutes, below); `auto` tries it first since 2026-11-27.
# Reading them takes the sanitized build longer than 10 s (exit 3 there).
answer_within=10
[[ -n "$sanitized" ]] && answer_within=120
within "$(deadline "$answer_within")" \
    "auto route on 200 000 generators answers (x, z) before --timeout $answer_within" 0 "z" -- \
    "$locus" groebner "$tmp/many.ideal" --timeout "$answer_within"
# Eight dense cubics in eight variables (6561 solutions): `auto` leaves the signature
# algorithm at the first large coefficients and the modular one runs into the deadline.
awk "$random_awk"' BEGIN { state = 11; print "vars: x1,x2,x3,x4,x5,x6,x7,x8"
    for (g = 0; g < 8; ++g) { line = ""
        for (i = 1; i <= 8; ++i) for (j = i; j <= 8; ++j) for (k = j; k <= 8; ++k)
            line = line sprintf("%s%d*x%d*x%d*x%d", (line == "" ? "" : "+"), 1 + next_random(99), i, j, k)
        for (i = 1; i <= 8; ++i) line = line sprintf("+%d*x%d", 1 + next_random(99), i)
        print line "+" (1 + next_random(99)) } }' >"$tmp/dense8.ideal"
within "$(deadline 2)" "auto route on eight dense cubics stops at --timeout 2" 3 "timeout" -- \
    "$locus" groebner "$tmp/dense8.ideal" --timeout 2
head -100001 "$tmp/many.ideal" >"$tmp/many100k.ideal"
within "$(deadline 1)" "modular on 100 000 generators stops at --timeout 1" 3 "timeout" -- \
    "$locus" groebner "$tmp/many100k.ideal" --algorithm modular --timeout 1
awk "$random_awk"' BEGIN { state = 3; print "vars: x,y,z"
    for (line = 0; line < 2; ++line) {
        for (i = 0; i < 60000; ++i)
            printf "%s%d*x^%d*y^%d*z^%d", (i ? "+" : ""), i + 1, next_random(40),
                next_random(40), next_random(40)
        print "" } }' >"$tmp/long.ideal"
within "$(deadline 1)" "two 60 000-term lines stop at --timeout 1" 3 "timeout" -- \
    "$locus" groebner "$tmp/long.ideal" --timeout 1
within 3 "(x+y+1)^32767 is refused before expansion (groebner)" 5 "could have more than 10000000 terms" -- \
    bash -c "printf 'vars: x,y\n(x+y+1)^32767\n' | \"$locus\" groebner -"
within 3 "(x+y+1)^32767 is refused before expansion (render)" 5 "could have more than 10000000 terms" -- \
    "$locus" render "(x+y+1)^32767" -o "$tmp/power.png"
within 3 "(1+s^2+t^2)^555 (a fuzzer's timeout) is refused before expansion" 5 "would take more than 10000000 limb products" -- \
    bash -c "printf 'vars: s,t\n(1+s^2+t^2)^555\n' | \"$locus\" groebner -"
printf 'params: t\nx = (1-t)^3015\ny = t\n' >"$tmp/wide.param"
within 3 "(1-t)^3015 in a .param (a fuzzer's timeout: wide coefficients) is refused" 5 "limb products" -- \
    "$locus" implicitize "$tmp/wide.param"
within "$(deadline 2)" "resultant route on x = t^30000 stops at --timeout 2" 3 "timeout" -- \
    "$locus" implicitize --method resultant -p t "x = t^30000" "y = t^30001" --timeout 2
within "$(deadline 1)" "render 8192x8192 stops at --timeout 1" 3 "nothing written to" -- \
    "$locus" render "$sphere" --size 8192x8192 --method exact --timeout 1 -o "$tmp/big.png"
if compgen -G "$tmp/big*" >/dev/null; then
    fail "a timed-out render left a file behind: $(ls "$tmp" | grep big)"
fi

## 3. --timeout values: one rule.
expect "--timeout inf is no limit" 0 "" -- "$locus" groebner "$cyclic" --timeout inf
expect "--timeout 1e10 is no limit" 0 "" -- "$locus" groebner "$cyclic" --timeout 1e10
for bad in nan -1 0 abc; do
    expect "--timeout $bad is an input error" 2 "--timeout: expected a positive number of seconds or 'inf' (no limit), found '$bad'" -- \
        "$locus" groebner "$cyclic" --timeout "$bad"
done

## 4. Memory and size limits.
within 3 "/dev/zero is rejected at the first byte" 2 "line 1, column 1: expected UTF-8 text, found the byte 0x00" -- \
    "$locus" groebner /dev/zero
within 3 "/dev/urandom is rejected at the first bad byte" 2 "expected UTF-8 text" -- \
    "$locus" groebner /dev/urandom
within 20 "an endless pipe stops at the input limit" 5 "input larger than the limit of 256 MiB" -- \
    bash -c "yes x+y | \"$locus\" groebner -"
printf '[[surface]]\nparam = "/dev/zero"\n' >"$tmp/zero_param.toml"
within 3 "a TOML param of /dev/zero" 2 "/dev/zero: line 1, column 1: expected UTF-8 text" -- \
    "$locus" render "$tmp/zero_param.toml" -o "$tmp/zero.png"
within 3 "an image beyond the pixel limit is refused before rendering" 5 "more than the limit of 67108864 pixels" -- \
    "$locus" render "$sphere" --size 16384x16384 --aov depth -o "$tmp/huge.exr"
awk 'BEGIN { printf "vars: "; for (i = 0; i < 20000; ++i) printf "%sx%d", (i ? "," : ""), i
    print ""; for (i = 0; i < 20000; ++i) print "x" i "^2-1" }' >"$tmp/vars.ideal"
within "$(deadline 2)" "20 000 variables stop at --timeout 2" 3 "timeout" -- \
    "$locus" groebner "$tmp/vars.ideal" --timeout 2
if [[ -z "$sanitized" ]]; then
    within 10 "20 000 variables under --max-memory 300M" 5 "out of memory (--max-memory 300M)" -- \
        "$locus" groebner "$tmp/vars.ideal" --max-memory 300M
fi
expect "--max-memory garbage" 2 "--max-memory: expected a number of bytes" -- "$locus" groebner "$cyclic" --max-memory lots

## 5. Write errors: every output is checked.
if [[ -w /dev/full ]]; then
    expect "groebner > /dev/full" 5 "cannot write" -- bash -c "\"$locus\" groebner $cyclic >/dev/full"
    expect "implicitize > /dev/full" 5 "cannot write" -- \
        bash -c "\"$locus\" implicitize -p u,v 'x = u' 'y = v' 'z = u*v' >/dev/full"
    expect "trace > /dev/full" 5 "cannot write" -- \
        bash -c "echo '0 0 5 0 0 -1' | \"$locus\" trace '$sphere' >/dev/full"
    expect "ideal > /dev/full" 5 "cannot write" -- \
        bash -c "\"$locus\" ideal eliminate $cyclic x0 >/dev/full"
fi
mkdir "$tmp/readonly" && chmod a-w "$tmp/readonly"
if ! touch "$tmp/readonly/probe" 2>/dev/null; then  # (root can write anyway)
    within 3 "render into a read-only folder fails before rendering" 2 "output" -- \
        "$locus" render "$sphere" -o "$tmp/readonly/x.png"
fi

## 6. The output path is checked before the work.
within "$before_work" "render -o /nonexistent/x.png" 2 "the folder '/nonexistent' does not exist" -- \
    "$locus" render "$sphere" --method exact --size 2000x2000 -o /nonexistent/x.png
within "$before_work" "render -o noext" 2 "no extension to name the image format" -- \
    "$locus" render "$sphere" --method exact --size 2000x2000 -o "$tmp/noext"
within "$before_work" "demo -o /nonexistent/x.png" 2 "the folder '/nonexistent' does not exist" -- \
    "$locus" demo -o /nonexistent/x.png

## 7. Validation, one rule per option.
expect "render --samples 0" 2 "--samples '0': expected N from 1 to 16" -- \
    "$locus" render "$sphere" --samples 0 -o "$tmp/s.png"
expect "render --threads -1" 2 "--threads '-1'" -- "$locus" render "$sphere" --threads -1 -o "$tmp/s.png"
expect "render --background -1,5,1e9" 2 "--background '-1,5,1e9': expected a linear colour" -- \
    "$locus" render "$sphere" --background -1,5,1e9 -o "$tmp/s.png"
printf '[[surface]]\nequation = "%s"\n[[light]]\ntype = "point"\n' "$sphere" >"$tmp/light.toml"
expect "a point light without a position" 2 "light.toml: line 3, column 1: light[1].position: a point light needs a position" -- \
    "$locus" render "$tmp/light.toml" -o "$tmp/s.png"
expect "ideal dimension with an extra argument" 2 "found a second argument 'extra'" -- \
    "$locus" ideal dimension "$cyclic" extra
expect "ideal equal - -" 2 "standard input can be read only once" -- \
    bash -c "\"$locus\" ideal equal - - <$cyclic"

## 8. Messages.
expect "a NUL byte is named, with its line and column" 2 "line 2, column 3: expected UTF-8 text, found the byte 0x00" -- \
    bash -c "printf 'vars: x\nx+\0y\n' | \"$locus\" groebner -"
expect "x² shows the character and its code point" 2 "found '²' (U+00B2)" -- \
    bash -c "printf 'vars: x\nx²\n' | \"$locus\" groebner -"
expect "a UTF-8 byte-order mark is accepted" 0 "" -- \
    bash -c "printf '\xef\xbb\xbfvars: x\nx^2\n' | \"$locus\" groebner -"
expect "a directory as input" 2 "is a directory, not a file" -- "$locus" groebner "$tmp"
printf '[[surface]]\nequation = "x^2+(y"\n' >"$tmp/bad.toml"
lacks "no doubled file prefix" "bad.toml: bad.toml" -- "$locus" render "$tmp/bad.toml" -o "$tmp/s.png"
lacks "no doubled equation prefix" "equation: equation:" -- "$locus" render "x^2+(y" -o "$tmp/s.png"
printf '[[surface]]\nequation = "%s"\n[camera]\neye = [1, 1, 1]\ntarget = [1, 1, 1]\n' "$sphere" >"$tmp/eye.toml"
expect "eye equal to target" 2 "eye.toml: line 4, column 7: camera.eye: the eye must differ from the target" -- \
    "$locus" render "$tmp/eye.toml" -o "$tmp/s.png"
printf '[[surface]]\nequation = "x-x"\n' >"$tmp/zero.toml"
expect "a zero polynomial in a scene" 2 "zero.toml: line 2, column 12: surface[1].equation: the zero polynomial" -- \
    "$locus" render "$tmp/zero.toml" -o "$tmp/s.png"
printf 'params: x\nx = x\ny = x^2\nz = x^3\n' >"$tmp/x.param"
expect "params: x" 2 "x.param: line 1, column 9: expected parameter names other than the coordinates" -- \
    "$locus" implicitize "$tmp/x.param"
expect "ideal eliminate F x,x" 2 "found 'x0' a second time" -- "$locus" ideal eliminate "$cyclic" x0,x0
printf '[[surface]]\nequation = "%s"\n[camera]\neye = [1, nan, 1]\n' "$sphere" >"$tmp/nan.toml"
expect "a NaN vector element" 2 "camera.eye: expected an array of three finite numbers, found nan" -- \
    "$locus" render "$tmp/nan.toml" -o "$tmp/s.png"
expect "an empty picture says why: outside the clip region" 0 \
    "no point of it was found inside its clip region, the sphere of radius 2 about (0, 0, 0)" -- \
    "$locus" render "x^2+y^2+z^2-100" --size 32x32 --clip-radius 2 -o "$tmp/empty.png"
expect "an empty picture says why: behind the camera" 0 "lies behind the camera" -- \
    "$locus" render "x^2+y^2+z^2-1" --size 32x32 --eye 0,0,5 --target 0,0,9 -o "$tmp/empty.png"
expect "an empty picture says why: no real point" 0 "no real point of it was found" -- \
    "$locus" render "x^2+y^2+z^2+1" --size 32x32 -o "$tmp/empty.png"
expect "--fit with --clip-radius" 2 "--fit and --clip-radius: give one" -- \
    "$locus" render "x^2+y^2+z^2-1" --fit --clip-radius 3 -o "$tmp/empty.png"

## 9. Exit codes: the table, and library input errors as input errors.
expect "the exit-code table is in --help" 0 "5 a resource limit" -- "$locus" --help
expect "--method interpolate on a degenerate map exits 2" 2 "method interpolate: " -- \
    "$locus" implicitize --method interpolate -p t "x = t" "y = t" "z = t"

summary
