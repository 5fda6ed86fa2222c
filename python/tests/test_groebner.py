# Gröbner bases from Python: the literature bases of tests/data/known, every algorithm giving
# the same basis, GF(p), the independent check, division, and random ideals against SymPy's
# Buchberger (an oracle that shares no code with locus).
import random

import pytest

import locus


def known_case(source_dir, name):
    ideal = locus.read_ideal(str(source_dir / "tests/data/known" / (name + ".ideal")))
    expected = (source_dir / "tests/data/known" / (name + ".expected")).read_text()
    return ideal, expected


def test_the_readme_line():
    basis = locus.groebner(["x^2+y", "y^2-1"], vars="x,y", order="lex")
    assert str(basis) == "y^2-1\nx^2+y"
    assert basis.stats["certified"]


@pytest.mark.parametrize("name", ["cyclic4_grevlex", "clo_2_7_lex", "katsura4_grevlex"])
def test_known_bases_under_every_algorithm(source_dir, name):
    path = source_dir / "tests/data/known" / (name + ".ideal")
    if not path.exists():
        pytest.skip(name + " not in tests/data/known")
    ideal, expected = known_case(source_dir, name)
    for algorithm in ("auto", "buchberger", "signature", "modular"):
        basis = locus.groebner(ideal, algorithm=algorithm, check=True)
        assert str(basis) + "\n" == expected, algorithm


def test_the_modular_route_proves_the_ideal_equal_where_it_can(source_dir):
    # katsura-5 has no zeros at infinity: the basis generates exactly the input's ideal.
    ideal = locus.read_ideal(str(source_dir / "bench/data/katsura5.ideal"))
    basis = locus.groebner(ideal, algorithm="modular")
    assert basis.stats["certified"] and basis.stats["ideal_equality"] == "proven"
    # cyclic-5 has zeros at infinity: that half rests on a lucky prime, and the stats say so.
    cyclic = locus.read_ideal(str(source_dir / "bench/data/cyclic5.ideal"))
    basis = locus.groebner(cyclic, algorithm="modular")
    assert basis.stats["ideal_equality"] == "not applicable"
    assert "infinity" in basis.stats["ideal_equality_argument"]


def test_prime_characteristic(source_dir):
    ideal = locus.read_ideal(str(source_dir / "bench/data/katsura5.ideal"))
    basis = locus.groebner(ideal, characteristic=65521, check=True)
    assert basis.stats["characteristic"] == 65521 and not basis.stats["certified"]
    assert "x0+2*x1+2*x2+2*x3+2*x4+65520" in str(basis)
    # verify() checks a basis over GF(p) in its own characteristic.
    assert locus.verify(basis, ideal) == (True, "")
    with pytest.raises(locus.InputError):
        locus.groebner(ideal, characteristic=65521, algorithm="buchberger")
    with pytest.raises(locus.InputError):
        locus.groebner(ideal, characteristic=65520)


def test_msolve_input_and_output(tmp_path):
    path = tmp_path / "three.ms"
    path.write_text("x,y,z\n32003\nx-y,\nz^2+2*z-1,\ny^2-z\n")
    ideal = locus.read_ideal(str(path))
    assert ideal.characteristic == 32003
    basis = locus.groebner(ideal)
    text = basis.format("msolve")
    assert text.splitlines()[:2] == ["x,y,z", "32003"]
    # What locus prints in msolve's format it reads back to the same basis.
    again = locus.groebner(locus.read_ideal(text))
    assert str(again) == str(basis)


def test_formats_and_normalized_round_trip():
    basis = locus.groebner(["x^2+y", "x*y-1"], vars="x,y")
    for fmt in locus.FORMATS:
        assert basis.format(fmt)
    assert "ring r = 0, (x,y), dp;" in basis.format("singular")
    R = basis.ring
    assert [R(line) for line in str(basis).splitlines()] == list(basis)


def test_division_identity():
    R = locus.Ring("x,y", order="lex")
    f = R("x^3*y - x*y^2 + 1")
    divisors = [R("x*y - 1"), R("y^2 - 1")]
    quotients, remainder = locus.divide(f, divisors)
    assert f == sum((q * g for q, g in zip(quotients, divisors)), R(0)) + remainder
    basis = locus.groebner(divisors)
    assert locus.reduce(f, basis) == locus.divide(f, list(basis))[1]


def test_verify_rejects_a_non_basis():
    R = locus.Ring("x,y")
    ok, why = locus.verify([R("x^2+y"), R("x*y-1")], [R("x^2+y"), R("x*y-1")])
    assert not ok and why
    basis = locus.groebner([R("x^2+y"), R("x*y-1")])
    assert locus.verify(basis, [R("x^2+y"), R("x*y-1")]) == (True, "")


def test_timeout_raises_timeout(source_dir):
    ideal = locus.read_ideal(str(source_dir / "bench/data/cyclic7.ideal"))
    for algorithm in ("buchberger", "signature", "modular"):
        with pytest.raises(locus.Timeout):
            locus.groebner(ideal, algorithm=algorithm, timeout=0.05)


def test_ideal_operations():
    ideal = locus.ideal
    twisted = ideal.eliminate(["x-t", "y-t^2", "z-t^3"], "t", vars="t,x,y,z")
    R = twisted.ring
    assert all(p.degree("t") == 0 for p in twisted)
    assert ideal.contains(twisted, [R("y-x^2"), R("z-x^3")])
    points = ideal.dimension(["x^2-1", "y^2-4"], vars="x,y")
    assert points["kind"] == "zero-dimensional" and points["solutions"] == 4
    assert points["hilbert_series"] == [1, 2, 1] and points["dimension"] == 0
    axes = ideal.dimension(["x*y"], vars="x,y")
    assert (axes["kind"], axes["dimension"], axes["degree"]) == ("positive-dimensional", 1, 2)
    assert axes["hilbert_polynomial"] == [2] and len(axes["independent_set"]) == 1
    assert ideal.dimension(["1"], vars="x,y")["kind"] == "unit"
    plane = ideal.dimension([], vars="x,y,z")  # the zero ideal
    assert plane["dimension"] == 3 and plane["degree"] == 1
    assert plane["independent_set"] == ["x", "y", "z"]
    member, cofactors, remainder = ideal.member("x^3-x", ["x^2-1"], vars="x")
    assert member and remainder == 0 and cofactors[0] == remainder.ring("x")
    assert ideal.radical_member("x", ["x^3"], vars="x")
    assert not ideal.radical_member("x+1", ["x^3"], vars="x")
    both = ideal.intersect(["x"], ["y"], vars="x,y")
    assert str(both) == "x*y"
    assert ideal.equal(ideal.quotient(["x*y"], ["y"], vars="x,y"), ["x"], vars="x,y")
    assert str(ideal.saturate(["x^2*y"], ["x"], vars="x,y")) == "y"


def random_ideal(rng, names):
    R = locus.Ring(names, order="grevlex")
    gens = []
    for _ in range(rng.randint(2, 3)):
        f = R(0)
        for _ in range(rng.randint(2, 4)):
            term = R(rng.randint(-5, 5))
            for v in R.gens():
                term = term * v ** rng.randint(0, 2)
            f = f + term
        if f:
            gens.append(f)
    return R, gens


def test_random_ideals_against_sympy():
    sympy = pytest.importorskip("sympy")
    rng = random.Random(2026)
    checked = 0
    for _ in range(12):
        R, gens = random_ideal(rng, "x,y,z")
        if not gens:
            continue
        symbols = sympy.symbols("x y z")
        theirs = sympy.groebner([locus.to_sympy(g) for g in gens], *symbols, order="grevlex",
                                domain="QQ")
        ours = locus.groebner(gens)
        # SymPy's reduced basis is monic too; compare as sets of polynomials of our ring.
        assert sorted(map(str, ours)) == sorted(
            str(locus.from_sympy(e, R)) for e in theirs.exprs), [str(g) for g in gens]
        checked += 1
    assert checked >= 10
