# Every output format round-trips: what locus prints for Singular, Macaulay2 and msolve it reads
# back to the same basis; the SymPy output, executed by Python, gives SymPy expressions equal to
# the basis; and where Singular is installed, Singular reads the Singular output as the same
# reduced basis under the same order (its std of it changes nothing).
import shutil
import subprocess

import pytest

import locus

CASES = [
    ("cyclic4_grevlex", None),
    ("clo_2_7_lex", None),
    ("clo_2_7_matrix", None),
    ("clo_2_8_implicit_elim", None),
]


def basis_of(source_dir, name):
    path = source_dir / "tests/data/known" / (name + ".ideal")
    if not path.exists():
        pytest.skip(name + " not in tests/data/known")
    return locus.groebner(locus.read_ideal(str(path)))


def by_names(poly, ring):
    return poly.in_ring(ring)


@pytest.mark.parametrize("name", [c[0] for c in CASES])
def test_locus_reads_its_own_output_back(source_dir, name):
    basis = basis_of(source_dir, name)
    for fmt in ("singular", "macaulay2", "msolve"):
        text = basis.format(fmt)
        back = locus.read_ideal(text)
        assert [str(by_names(p, basis.ring)) for p in back] == [str(p) for p in basis], fmt
        if fmt != "msolve":  # msolve's format has no order: grevlex
            again = locus.groebner(back)
            assert [str(by_names(p, basis.ring)) for p in again] == [str(p) for p in basis], fmt


@pytest.mark.parametrize("name", [c[0] for c in CASES])
def test_sympy_output_executes_to_the_same_basis(source_dir, name):
    pytest.importorskip("sympy")
    basis = basis_of(source_dir, name)
    namespace = {}
    exec(basis.format("sympy"), namespace)
    assert [locus.from_sympy(e, basis.ring) for e in namespace["G"]] == list(basis)


def test_sympy_output_with_reserved_names():
    pytest.importorskip("sympy")
    basis = locus.groebner(["lambda*x - 1/3", "x^2 - 2"], vars="lambda,x", order="lex")
    namespace = {}
    exec(basis.format("sympy"), namespace)
    assert [locus.from_sympy(e, basis.ring) for e in namespace["G"]] == list(basis)


@pytest.mark.skipif(shutil.which("Singular") is None, reason="Singular is not installed")
@pytest.mark.parametrize("name", [c[0] for c in CASES] + ["reserved"])
def test_singular_reads_the_singular_output(source_dir, name):
    if name == "reserved":
        basis = locus.groebner(["r*ring - std", "ring^2 - 1/3", "std^3 - r"],
                               vars="r,ring,std", order="lex")
    else:
        basis = basis_of(source_dir, name)
    script = basis.format("singular") + (
        "option(redSB); ideal S = std(G);\n"
        "print(size(reduce(S, G)) == 0 && size(reduce(G, S)) == 0 && size(S) == size(G));\n"
        "quit;\n")
    result = subprocess.run(["Singular", "-q"], input=script, capture_output=True, text=True,
                            timeout=60)
    assert result.stdout.split()[-1:] == ["1"], result.stdout + result.stderr


@pytest.mark.skipif(shutil.which("M2") is None, reason="Macaulay2 is not installed")
@pytest.mark.parametrize("name", [c[0] for c in CASES])
def test_macaulay2_reads_the_macaulay2_output(source_dir, name):
    basis = basis_of(source_dir, name)
    # The same ideal, and the printed basis is already Macaulay2's Gröbner basis for its order:
    # the leading terms agree.
    script = basis.format("macaulay2") + (
        "H = ideal gens gb G;\n"
        "print toString(H == G and ideal leadTerm gens gb G == ideal leadTerm gens G)\n"
        "exit 0\n")
    result = subprocess.run(["M2", "--script", "/dev/stdin"], input=script, capture_output=True,
                            text=True, timeout=120)
    assert result.stdout.split()[-1:] == ["true"], result.stdout + result.stderr
