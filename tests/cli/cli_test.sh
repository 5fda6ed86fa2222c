#!/usr/bin/env bash
# End-to-end checks of the locus executable: outputs, error messages and exit codes.
# Usage: tests/cli/cli_test.sh PATH/TO/locus   (run from the source root; ctest does this)
set -uo pipefail
locus="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/expect.sh"

known=tests/data/known
# Only the subcommand named first is built (cli/main.cpp): its help has its options, the top-level
# help lists every subcommand, and a name that is not one is still refused with the list.
expect "top-level help lists every subcommand" 0 "view" -- "$locus" --help
expect "top-level help lists groebner" 0 "groebner" -- "$locus" --help
expect "render's help has its options" 0 "--clip-radius" -- "$locus" render --help
expect "groebner's help has its options" 0 "--algorithm" -- "$locus" groebner --help
expect "an unknown subcommand is refused" 2 "A subcommand is required" -- "$locus" rendr x
expect "a subcommand's option before it is refused" 2 "" -- "$locus" --clip-radius 2 render x
# The process ends with _Exit after run_app: what went to a pipe must all be there.
expect "output through a pipe is complete" 0 "" -- \
    bash -c "\"$locus\" groebner $known/cyclic4_lex.ideal | cat | diff - $known/cyclic4_lex.expected"
expect "groebner prints the expected basis" 0 "" -- \
    bash -c "\"$locus\" groebner $known/cyclic4_lex.ideal | diff - $known/cyclic4_lex.expected"
expect "groebner reads standard input" 0 "" -- \
    bash -c "\"$locus\" groebner - < $known/katsura4_grevlex.ideal | diff - $known/katsura4_grevlex.expected"
expect "check verifies" 0 "check: ok" -- "$locus" groebner $known/cyclic4_grevlex.ideal --check
expect "stats go to stderr" 0 "reductions to zero" -- "$locus" groebner $known/cyclic4_grevlex.ideal --stats
expect "modular on two threads certifies" 0 "certified over Q" -- \
    "$locus" groebner $known/cyclic4_grevlex.ideal --algorithm modular --threads 2 --stats
expect "auto honours --no-certify when it goes modular" 0 "NOT certified" -- \
    "$locus" groebner bench/data/cyclic7.ideal --no-certify --stats
expect "groebner: negative --threads" 2 "--threads -1: expected a positive count" -- \
    "$locus" groebner $known/cyclic4_grevlex.ideal --threads -1
expect "order override" 0 "" -- \
    bash -c "\"$locus\" groebner $known/cyclic4_grevlex.ideal --order lex | diff - $known/cyclic4_lex.expected"
expect "singular format" 0 "ring r = 0, (x0,x1,x2,x3), dp;" -- \
    "$locus" groebner $known/cyclic4_grevlex.ideal --format singular

printf 'vars: x,y\nx^2+y\n  x*(y+1\n' > "$tmp/unbalanced.ideal"
expect "unbalanced parenthesis: line and column" 2 "line 3, column 9: expected ')' to close" -- \
    "$locus" groebner "$tmp/unbalanced.ideal"
printf 'vars: x,y\nx^2+u\n' > "$tmp/undeclared.ideal"
expect "undeclared variable" 2 "line 2, column 5: expected a declared variable, found 'u'" -- \
    "$locus" groebner "$tmp/undeclared.ideal"
printf 'vars: x,y\norder: revlex\nx\n' > "$tmp/order.ideal"
expect "unknown order" 2 "line 2, column 8: expected an order" -- "$locus" groebner "$tmp/order.ideal"
printf 'vars: x,y\nx^-1\n' > "$tmp/negative.ideal"
expect "negative exponent" 2 "line 2, column 3: expected a non-negative integer exponent" -- \
    "$locus" groebner "$tmp/negative.ideal"
: > "$tmp/empty.ideal"
expect "empty file" 2 "line 1, column 1: expected a 'vars:' line" -- "$locus" groebner "$tmp/empty.ideal"
expect "missing file" 2 "cannot open" -- "$locus" groebner "$tmp/nothing.ideal"
expect "bad --order" 2 "--order" -- "$locus" groebner $known/cyclic4_grevlex.ideal --order 'weights(1)'
expect "bad --format" 2 "expected normalized, singular, macaulay2, latex, msolve, sympy, maple or mathematica" -- \
    "$locus" groebner $known/cyclic4_grevlex.ideal --format maxima
expect "timeout exits 3" 3 "timeout" -- "$locus" groebner bench/data/cyclic6.ideal --timeout 0.05 --algorithm buchberger
expect "modular timeout exits 3" 3 "timeout" -- "$locus" groebner bench/data/cyclic7.ideal --timeout 0.2
expect "ideal operations honour --timeout" 3 "not complete at the deadline" -- "$locus" ideal dimension bench/data/katsura9.ideal --timeout 0.05
printf 'vars: a,b,c,d,e,f,g,h\norder: grevlex\na^12\nb^12\nc^12\nd^12\ne^12\nf^12\ng^12\nh^12\n' >"$tmp/box.ideal"
expect "dimension counts a box of 12^8 standard monomials at once" 0 "zero-dimensional: 429981696 solutions" -- "$locus" ideal dimension "$tmp/box.ideal" --timeout 5
expect "modular result is certified" 0 "certified over Q" -- "$locus" groebner bench/data/cyclic6.ideal --algorithm modular --stats
expect "f4 modulo a prime" 0 "x0+2*x1+2*x2+2*x3+2*x4+65520" -- "$locus" groebner bench/data/katsura5.ideal --algorithm f4 --prime 65521
expect "f4: not a prime" 2 "expected a prime below 2^31" -- "$locus" groebner bench/data/katsura5.ideal --algorithm f4 --prime 65520
expect "--prime over Q without f4 is refused, not ignored" 2 "applies to --algorithm f4" -- "$locus" groebner bench/data/katsura5.ideal --prime 65521
# Sessions pasted from Singular and Macaulay2, and the other systems' output formats.
printf 'LIB "poly.lib"; // comment\nring r = 0, (x,y), lp;\nideal I = x^2+y,\n  y^2-1;\nideal J = std(I);\n' > "$tmp/pasted.sing"
expect "a pasted Singular session" 0 "x^2+y" -- "$locus" groebner "$tmp/pasted.sing"
printf 'R = ZZ/7[x,y, MonomialOrder => Lex] -- comment\nI = ideal(x^2+y, y^2-1)\n' > "$tmp/pasted.m2"
expect "a pasted Macaulay2 session over ZZ/7" 0 "y^2+6" -- "$locus" groebner "$tmp/pasted.m2"
expect "a Singular paste with a local order is refused at its column" 2 "line 1, column 20" -- \
    bash -c "printf 'ring r = 0, (x,y), ds;\nideal I = x;\n' | '$locus' groebner -"
expect "--format sympy" 0 "G = [" -- "$locus" groebner "$tmp/pasted.sing" --format sympy
expect "--format mathematica" 0 "G = {" -- "$locus" groebner "$tmp/pasted.sing" --format mathematica
expect "--format maple" 0 "G := [" -- "$locus" groebner "$tmp/pasted.sing" --format maple
expect "ideal member cofactors follow --format" 0 "cofactor 1: 3 x^{2} z^{2}" -- \
    "$locus" ideal member tests/data/known/clo_2_8_membership_grlex.ideal '-4*x^2*y^2*z^2+y^6+3*z^5' --format latex
# locus view: the first line names the address; --timeout ends serving with exit 0; bad input
# is refused before anything is served. The deadline counts from the start of the process: a
# server not yet listening when it passes stops without ever saying where, which 0.5 s allowed
# on a loaded machine (this failed once beside a build on both cores, 2026-11-29).
expect "view serves and says where" 0 "serving on http://127.0.0.1:" -- \
    "$locus" view 'x^2+y^2+z^2-r' --port 0 --timeout 3
expect "view: a malformed equation is refused at its column" 2 "column 7" -- \
    "$locus" view 'x^2 + * y' --port 0 --timeout 0.5
expect "view: a port out of range" 2 "--port 70000" -- "$locus" view --port 70000 --timeout 0.5
# Over GF(p) from the input: a characteristic: line, or msolve's format.
{ echo "characteristic: 101"; cat bench/data/katsura4.ideal; } >"$tmp/k4p.ideal"
expect "characteristic p: computed modulo p and checked there" 0 "check: ok modulo 101" -- \
    "$locus" groebner "$tmp/k4p.ideal" --check
expect "characteristic p: Singular's ring says so" 0 "ring r = 101, (x0,x1,x2,x3), dp;" -- \
    "$locus" groebner "$tmp/k4p.ideal" --format singular
expect "characteristic p: the modular route over Q is refused" 2 "computes over Q" -- \
    "$locus" groebner "$tmp/k4p.ideal" --algorithm modular
expect "characteristic p: a different --prime is refused" 2 "the input has characteristic 101" -- \
    "$locus" groebner "$tmp/k4p.ideal" --prime 103
expect "characteristic p: ideal operations are refused" 2 "compute over Q" -- \
    "$locus" ideal dimension "$tmp/k4p.ideal"
printf 'vars: x\ncharacteristic: 5\nx-2/5\n' >"$tmp/fifth.ideal"
expect "characteristic 5: 2/5 has no residue" 2 "line 3, column 1: expected coefficients whose denominators" -- \
    "$locus" groebner "$tmp/fifth.ideal"
printf 'x,y,z\n32003\nx^2+y^2+z^2-1,\n  x*y-z,\nx-y\n' >"$tmp/three.ms"
expect "msolve's format in characteristic p" 0 "y^2+32002*z" -- "$locus" groebner "$tmp/three.ms"
expect "msolve's format out" 0 "" -- bash -c \
    "\"$locus\" groebner $tmp/three.ms --format msolve | diff - <(printf 'x,y,z\n32003\nx+32002*y,\nz^2+2*z+32002,\ny^2+32002*z\n')"
expect "msolve's format on standard input, over Q" 0 "x*y-3" -- bash -c \
    "printf 'x,y\n0\nx^2-1/2*y,\nx*y-3\n' | \"$locus\" groebner -"
printf 'x,y\n0\nx-1,\n' >"$tmp/trailing.ms"
expect "msolve: a trailing comma names its place" 2 "line 3, column 5: expected a polynomial" -- \
    "$locus" groebner "$tmp/trailing.ms"
printf 'x,y\n12\nx\n' >"$tmp/twelve.ms"
expect "msolve: a characteristic that is not prime" 2 "line 2, column 1: expected the characteristic" -- \
    "$locus" groebner "$tmp/twelve.ms"
expect "unknown algorithm" 2 "expected auto, buchberger, signature, f4 or modular" -- "$locus" groebner bench/data/katsura5.ideal --algorithm magic
expect "signature algorithm prints the expected basis" 0 "" -- \
    bash -c "\"$locus\" groebner $known/cyclic4_lex.ideal --algorithm signature | diff - $known/cyclic4_lex.expected"
expect "signature statistics name its criteria" 0 "removed as syzygies" -- \
    "$locus" groebner bench/data/eco6.ideal --algorithm signature --stats
printf 'vars: x,y\norder: weights(16000,1)\nx^2-y\nx*y-1\n' > "$tmp/heavy.ideal"
expect "signature: a signature past the packed range is an input error" 2 "exponent overflow" -- \
    "$locus" groebner "$tmp/heavy.ideal" --algorithm signature
expect "auto answers it with Buchberger and says so" 0 "algorithm: buchberger" -- \
    "$locus" groebner "$tmp/heavy.ideal" --stats
expect "signature timeout exits 3" 3 "the basis is not complete" -- \
    "$locus" groebner bench/data/cyclic7.ideal --algorithm signature --timeout 0.05

printf 'vars: x,y,z\nx^2-y\nx*y-z\n' > "$tmp/twisted.ideal"
expect "member with cofactors" 0 "cofactor 2:" -- "$locus" ideal member "$tmp/twisted.ideal" "x^3-z"
expect "not a member exits 1" 1 "remainder:" -- "$locus" ideal member "$tmp/twisted.ideal" "x+1"
expect "eliminate" 0 "y^3-z^2" -- "$locus" ideal eliminate "$tmp/twisted.ideal" x
expect "dimension" 0 "positive-dimensional" -- "$locus" ideal dimension "$tmp/twisted.ideal"
printf 'vars: x,y,z\nx\n' > "$tmp/x.ideal"
expect "contains: no" 1 "no" -- "$locus" ideal contains "$tmp/twisted.ideal" "$tmp/x.ideal"
expect "radical membership" 0 "yes" -- "$locus" ideal radical-member "$tmp/twisted.ideal" "y^3-z^2"
# The zero ideal (a file whose only generator is 0) is an argument like any other: I : 0 = <1>,
# 0 : I = 0, I ∩ 0 = 0, 0 ⊆ I, f ∈ 0 only for f = 0 (these were "the ideal has no generators").
printf 'vars: x,y,z
0
' > "$tmp/zero.ideal"
expect "quotient by the zero ideal is the unit ideal" 0 "  1;" -- \
    "$locus" ideal quotient "$tmp/twisted.ideal" "$tmp/zero.ideal" --format singular
expect "saturation of the zero ideal is zero" 0 "ideal G = 0;" -- \
    "$locus" ideal saturate "$tmp/zero.ideal" "$tmp/twisted.ideal" --format singular
expect "intersection with the zero ideal is zero" 0 "ideal(0_R)" -- \
    "$locus" ideal intersect "$tmp/twisted.ideal" "$tmp/zero.ideal" --format macaulay2
expect "sum with the zero ideal" 0 "" -- \
    bash -c "diff <(\"$locus\" ideal sum \"$tmp/zero.ideal\" \"$tmp/twisted.ideal\") <(\"$locus\" groebner \"$tmp/twisted.ideal\")"
expect "the zero ideal contains no x" 1 "no" -- "$locus" ideal contains "$tmp/zero.ideal" "$tmp/x.ideal"
expect "every ideal contains the zero ideal" 0 "yes" -- \
    "$locus" ideal contains "$tmp/twisted.ideal" "$tmp/zero.ideal"
expect "x is not in the zero ideal" 1 "remainder: x" -- "$locus" ideal member "$tmp/zero.ideal" "x"
expect "nor in its radical" 1 "no" -- "$locus" ideal radical-member "$tmp/zero.ideal" "x"
expect "demo implicitizes and renders" 0 "verified: vanishes identically" -- "$locus" demo -o "$tmp/demo.png"
expect "demo wrote its PNG" 0 "" -- test -s "$tmp/demo.png"

expect "implicitize inline" 0 "verified" -- "$locus" implicitize -p s,t "x = s*t" "y = s" "z = t^2"
printf 'params: t\nx = (1-t^2)/(1+t^2)\ny = 2*t/(1+t^2)\n' > "$tmp/circle.param"
expect "implicitize file" 0 "" -- bash -c "\"$locus\" implicitize $tmp/circle.param 2>/dev/null | grep -qx 'x^2+y^2-1'"
printf 'params: u,v\nx = u*cos(v)\ny = u*sin(v)\nz = v\n' > "$tmp/helicoid.param"
expect "implicitize refuses the helicoid" 2 "line 4, column 5: expected the angle v only inside sin and cos" -- \
    "$locus" implicitize "$tmp/helicoid.param"
expect "implicitize refuses cos(u), u" 2 "the angle u only inside sin and cos" -- \
    "$locus" implicitize -p u "x = cos(u)" "y = u"
expect "implicitize expands multiple angles" 0 "" -- \
    bash -c "\"$locus\" implicitize -p u 'x = cos(2*u)' 'y = sin(3*u)' 2>/dev/null | grep -qx '4\*x^3+2\*y^2-3\*x-1'"
expect "implicitize verifies trigonometric maps as written" 0 "as written (sin^2 + cos^2 = 1)" -- \
    "$locus" implicitize bench/data/implicit/torus_trig.param
expect "implicitize not principal" 0 "not principal" -- "$locus" implicitize -p t "x=t" "y=t^2" "z=t^3"
printf 'params: t\nx = t\nx = t^2\n' > "$tmp/twice.param"
expect "implicitize bad input" 2 "line 3, column 1" -- "$locus" implicitize "$tmp/twice.param"

expect "implicitize by resultant" 0 "method: resultant" -- \
    "$locus" implicitize -p t --method resultant "x = t^2" "y = t^3"
expect "resultant refuses space curves" 2 "plane curves" -- \
    "$locus" implicitize -p t --method resultant "x=t" "y=t^2" "z=t^3"

# Rendering and tracing.
expect "render an equation to PNG" 0 "wrote $tmp/sphere.png" -- \
    "$locus" render "x^2+y^2+z^2-1" -o "$tmp/sphere.png" --size 48x32 --samples 2 --threads 1
expect "the PNG exists" 0 "" -- test -s "$tmp/sphere.png"
# ISA-L is loaded on the first PNG: one that cannot be loaded is a failed write (exit 5), names
# the package, and leaves no file.
mkdir -p "$tmp/broken-lib" && echo "not a library" > "$tmp/broken-lib/libisal.so.2"
expect "PNG without a loadable ISA-L: a resource limit" 5 "Debian package libisal2" -- \
    env LD_LIBRARY_PATH="$tmp/broken-lib" "$locus" render "x^2+y^2+z^2-1" -o "$tmp/nolib.png" --size 16x16
expect "PNG without a loadable ISA-L: nothing written" 1 "" -- \
    bash -c "ls -a \"$tmp\" | grep -q nolib"
# An ellipsoid with three different axes: every turned frame differs from the still.
expect "turntable: three numbered frames" 0 "turntable: 3 frames" -- \
    "$locus" render "4*x^2+y^2+z^2/4-1" -o "$tmp/turn.png" --size 16x16 --turntable 3 --threads 1
expect "turntable: the frames exist" 0 "" -- \
    test -s "$tmp/turn_0001.png" -a -s "$tmp/turn_0002.png" -a -s "$tmp/turn_0003.png" -a ! -e "$tmp/turn_0004.png"
"$locus" render "4*x^2+y^2+z^2/4-1" -o "$tmp/still.png" --size 16x16 --threads 1 2>/dev/null
expect "turntable: frame 1 is the still image" 0 "" -- cmp "$tmp/still.png" "$tmp/turn_0001.png"
expect "turntable: frame 2 is turned" 1 "" -- cmp -s "$tmp/still.png" "$tmp/turn_0002.png"
expect "turntable: a count of 0" 2 "--turntable '0': expected a frame count from 1 to 100000" -- \
    "$locus" render "x^2+y^2+z^2-1" -o "$tmp/turn.png" --turntable 0
# Framing: a torus with R = 3 lies outside the default clip sphere (radius 2), so it is framed
# on its extent; --fit replaces a scene file's clip and camera.
torus3='(x^2+y^2+z^2+8)^2-36*(x^2+y^2)'
framed=$("$locus" render "$torus3" -o "$tmp/torus3.png" --size 24x24 2>&1)
if grep -q "no ray hit" <<<"$framed" || ! grep -q " hits" <<<"$framed"; then
    fail "a torus with R = 3 is framed without flags"; echo "$framed" | head -3
else
    echo "ok   a torus with R = 3 is framed without flags"; passes=$((passes + 1))
fi
printf '[[surface]]\nequation = "%s"\nclip_radius = 1\n[camera]\neye = [0, 0, 30]\n' "$torus3" \
    >"$tmp/torus3.toml"
expect "a scene clipped away says so" 0 "no point of it was found inside its clip region" -- \
    "$locus" render "$tmp/torus3.toml" -o "$tmp/torus3.png" --size 24x24
fitted=$("$locus" render "$tmp/torus3.toml" --fit -o "$tmp/torus3.png" --size 24x24 2>&1)
if grep -q "no ray hit" <<<"$fitted"; then
    fail "--fit replaces the scene's clip region"; echo "$fitted" | head -3
else
    echo "ok   --fit replaces the scene's clip region"; passes=$((passes + 1))
fi
expect "--fit on an unbounded surface warns" 0 "is not bounded" -- \
    "$locus" render "x^2+y^2-1" --fit -o "$tmp/cylinder.png" --size 16x16
printf '[camera]\neye = [0, 0, 5]\nframes = 3\n[[camera.key]]\neye = [5, 0, 0]\n[[surface]]\nequation = "x^2+y^2+z^2-1"\n' \
    >"$tmp/path.toml"
expect "a camera path renders its frames" 0 "camera path: 3 frames in" -- \
    "$locus" render "$tmp/path.toml" -o "$tmp/path.png" --size 16x16 --threads 1
[[ -s "$tmp/path_0003.png" && ! -e "$tmp/path_0004.png" ]] && { echo "ok   camera path files"; passes=$((passes + 1)); } ||
    fail "camera path files"
expect "a camera path and --turntable" 2 "give one" -- \
    "$locus" render "$tmp/path.toml" -o "$tmp/path.png" --size 16x16 --turntable 4
expect "a camera path and --fit" 2 "--fit and the scene's camera path" -- \
    "$locus" render "$tmp/path.toml" -o "$tmp/path.png" --size 16x16 --fit
# Opposite up directions blend to zero halfway: refused before any frame is written.
printf '[camera]\neye = [0, 0, 5]\nframes = 3\n[[camera.key]]\nup = [0, -1, 0]\n[[surface]]\nequation = "x^2+y^2+z^2-1"\n' \
    >"$tmp/flip.toml"
expect "a degenerate camera between keys" 2 "camera path, frame 2:" -- \
    "$locus" render "$tmp/flip.toml" -o "$tmp/flip.png" --size 16x16
[[ ! -e "$tmp/flip_0001.png" ]] && { echo "ok   no frame written"; passes=$((passes + 1)); } ||
    fail "no frame written"
expect "square-free part reported" 0 "rendering its square-free part x^2+y^2+z^2-1" -- \
    "$locus" render "(x^2+y^2+z^2-1)^2" -o "$tmp/squared.png" --size 16x16
expect "render AOVs" 0 "wrote $tmp/aov.depth.exr" -- \
    "$locus" render "x^2-y^2*z" -o "$tmp/aov.png" --size 16x16 --aov depth,normal,work
expect "render a parametrization" 0 "implicit equation" -- \
    "$locus" render --param bench/data/implicit/whitney.param -o "$tmp/whitney.png" --size 16x16
expect "render: zero polynomial" 2 "the zero polynomial defines no surface" -- \
    "$locus" render "x-x" -o "$tmp/zero.png"
expect "render: constant" 2 "a non-zero constant defines no surface" -- \
    "$locus" render "3" -o "$tmp/constant.png"
expect "render: bad equation names the column" 2 "line 1, column 5" -- \
    "$locus" render "x^2+*y" -o "$tmp/bad.png"
expect "render: degenerate camera" 2 "camera.eye" -- \
    "$locus" render "x^2+y^2+z^2-1" --eye 1,1,1 --target 1,1,1 -o "$tmp/cam.png"
expect "render: bad flag value" 2 "--size '12': expected WIDTHxHEIGHT" -- \
    "$locus" render "x^2+y^2+z^2-1" --size 12 -o "$tmp/size.png"
expect "render: unknown method" 2 "--method: 'magic': expected certified, sturm, bernstein, laguerre, eigen, sphere-gradient, sphere-lipschitz or exact" -- \
    "$locus" render "x^2+y^2+z^2-1" --method magic -o "$tmp/m.png"
expect "implicitize: unknown method" 2 "--method: 'fast': expected auto, groebner, resultant, interpolate or dixon" -- \
    "$locus" implicitize -p t "x = t" "y = t^2" --method fast
expect "render: --shadows takes on or off" 2 "--shadows: 'yes': expected on or off" -- \
    "$locus" render "x^2+y^2+z^2-1" --shadows yes -o "$tmp/m.png"
expect "render: unknown AOV" 2 "--aov: 'albedo': expected depth, normal or work" -- \
    "$locus" render "x^2+y^2+z^2-1" --aov depth,albedo -o "$tmp/m.png"
printf '[[surface]]\nequation = "x^2+y^2+z^2-1"\nradius = 2\n' > "$tmp/bad.toml"
expect "render: unknown scene key" 2 "bad.toml: line 3, column 1: surface[1].radius: unknown key" -- \
    "$locus" render "$tmp/bad.toml" -o "$tmp/scene.png"
printf '[image]\nwidth = 24\nheight = 16\n[[surface]]\nequation = "x^2+y^2+z^2-1"\n[render]\nmethod = "bernstein"\n' > "$tmp/good.toml"
expect "render a scene file" 0 "rendered 24x16, 1×1 samples, method bernstein" -- \
    "$locus" render "$tmp/good.toml" -o "$tmp/scene.png"
# An equation far from the origin is rendered in its own frame: expanded at the origin,
# (x-1e8)^2+y^2+z^2-1 cancels in doubles, and sturm drew 854 hits where there are 368.
printf '[[surface]]\nequation = "(x-1e8)^2+y^2+z^2-1"\nclip = "sphere"\nclip_center = [1e8, 0, 0]\nclip_radius = 2\n' > "$tmp/far.toml"
expect "a far equation: sturm and laguerre draw the certified picture" 0 "" -- bash -c \
    "for m in certified sturm laguerre; do \"$locus\" render \"$tmp/far.toml\" -o \"$tmp/far.png\" --size 48x48 --method \$m 2>&1 | grep -o '[0-9]* hits'; done | uniq | wc -l | grep -qx 1"
printf '[[object]]\ntype = "smooth_union"\nk = 0.3\n[[object.children]]\ntype = "sphere"\n[[object.children]]\ntype = "algebraic"\nparam = "bench/data/implicit/steiner_roman.param"\nscale = 2\n' > "$tmp/tree.toml"
expect "render an SDF scene with an implicitized leaf" 0 "primitive evaluations per primary ray" -- \
    "$locus" render "$tmp/tree.toml" -o "$tmp/tree.png" --size 24x16
printf '[[object]]\ntype = "union"\n[[object.children]]\ntype = "sphre"\n' > "$tmp/badtree.toml"
expect "render: unknown node type names the node" 2 "badtree.toml: line 4, column 8: object[1].children[1].type: expected a node type" -- \
    "$locus" render "$tmp/badtree.toml" -o "$tmp/tree.png"
expect "render --timeout covers implicitizing --param" 3 "nothing written to" -- \
    "$locus" render --param bench/data/implicit/bezier_triangle3.param --timeout 0.01 \
    -o "$tmp/bezier.png" --size 16x16
expect "render timeout exits 3 and writes nothing" 3 "nothing written to" -- \
    "$locus" render "x^2+y^2+z^2-1" --method exact --size 400x400 --samples 3 --timeout 0.05 \
    -o "$tmp/timeout.png"
if [[ -e "$tmp/timeout.png" ]]; then
    fail "render timeout wrote an image"
fi
expect "resultant honours --timeout" 3 "timeout: stopped after 1 s" -- \
    "$locus" implicitize bench/data/implicit/bezier_triangle3.param --method resultant --timeout 1
expect "the teapot: one verified equation a patch" 0 "" -- bash -c \
    "\"$locus\" implicitize bench/data/implicit/teapot.bpt 2>\"$tmp/teapot.err\" | grep -c . | grep -qx 32 && test \$(grep -c 'verified: vanishes' \"$tmp/teapot.err\") = 32"
expect "the bicubic patch by the Dixon route" 0 "degree 18, 1330 terms, irreducible" -- \
    "$locus" implicitize bench/data/implicit/bezier_bicubic.param
printf '1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 one\n' >"$tmp/bad.bpt"
expect "a malformed .bpt names line and column" 2 "line 6, column 5: expected a decimal number" -- \
    "$locus" implicitize "$tmp/bad.bpt"
printf 'bezier: 1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n' >"$tmp/bilinear.param"
expect "a bezier: patch in a .param" 0 "" -- bash -c \
    "\"$locus\" implicitize $tmp/bilinear.param 2>/dev/null | grep -qx 'x\*y-z'"
# The teapot's 32 patches take 1.4 s on one thread of a fast machine (0.2 s the bicubic alone).
expect "dixon honours --timeout" 3 "timeout" -- \
    "$locus" implicitize bench/data/implicit/teapot.bpt --method dixon --threads 1 --timeout 0.2
expect "dixon refuses curves" 2 "applies to surfaces" -- \
    "$locus" implicitize -p t --method dixon "x = t" "y = t^2"
expect "render the teapot's 32 patches, trimmed" 0 "32 patches implicitized and verified" -- \
    "$locus" render bench/data/implicit/teapot.bpt --method sturm --size 40x40 -o "$tmp/teapot.png"
test -s "$tmp/teapot.png" || fail "the teapot render wrote no picture"
expect "resultant under --timeout still answers" 0 "x^2*y^2+x^2*z^2+y^2*z^2-x*y*z" -- \
    "$locus" implicitize bench/data/implicit/steiner_roman.param --method resultant --timeout 20
expect "trace prints hits and misses" 0 "" -- bash -c \
    "printf '0 0 5 0 0 -1\n3 3 3 1 0 0\n' | \"$locus\" trace 'x^2+y^2+z^2-1' --method exact | diff - <(printf '4\nmiss\n')"
expect "trace: bad ray names line and column" 2 "line 2, column 7: expected a finite decimal number (ray: ox oy oz dx dy dz), found 'x'" -- \
    bash -c "printf '0 0 5 0 0 -1\n0 0 5 x 0 -1\n' | \"$locus\" trace 'x^2+y^2+z^2-1'"

summary
