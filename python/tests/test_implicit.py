# Implicitization from Python: the equation vanishes on the parametrization, checked here by
# SymPy's substitution (independent of locus's own proof), for every route that applies.
import pytest

import locus

ENNEPER = {"params": "u,v", "x": "u - u^3/3 + u*v^2", "y": "v - v^3/3 + v*u^2", "z": "u^2 - v^2"}


def vanishes_by_sympy(equation, param):
    sympy = pytest.importorskip("sympy")
    u, v = sympy.symbols("u v")
    x, y, z = sympy.symbols("x y z")
    image = {s: sympy.sympify(param[name].replace("^", "**"), locals={"u": u, "v": v})
             for s, name in ((x, "x"), (y, "y"), (z, "z"))}
    expr = sympy.sympify(str(equation).replace("^", "**"), locals={"x": x, "y": y, "z": z})
    return sympy.expand(expr.subs(image, simultaneous=True)) == 0


def test_enneper_by_every_route():
    for method in ("auto", "groebner", "resultant", "interpolate", "dixon"):
        result = locus.implicitize(ENNEPER, method=method)
        assert result.equation is not None and result.verified
        assert result.equation.degree() == 9, method
        assert vanishes_by_sympy(result.equation, ENNEPER), method


def test_text_file_and_angles(tmp_path):
    path = tmp_path / "torus.param"
    path.write_text("params: u,v\nx = (2 + cos(v))*cos(u)\ny = (2 + cos(v))*sin(u)\n"
                    "z = sin(v)\n")
    torus = locus.implicitize(str(path))
    assert torus.equation.degree() == 4 and torus.angles == ["u", "v"]
    R = torus.equation.ring
    x, y, z = R.gens()
    expected = (x**2 + y**2 + z**2 + 3) ** 2 - 16 * (x**2 + y**2)
    assert torus.equation in (expected, -expected)


def test_curves_and_images_that_are_not_surfaces():
    cusp = locus.implicitize("params: t\nx = t^2\ny = t^3\n")
    assert str(cusp.equation) in ("x^3-y^2", "-x^3+y^2")
    twisted = locus.implicitize("params: t\nx = t\ny = t^2\nz = t^3\n")
    assert twisted.equation is None and twisted.image == "lower-dimensional"
    assert len(twisted.generators) >= 2


def test_bad_input():
    with pytest.raises(locus.ParseError) as caught:
        locus.implicitize("params: u,v\nx = u +\ny = v\nz = u*v\n")
    assert caught.value.line == 2
    with pytest.raises(locus.ParseError):
        locus.implicitize("params: u,v\nx = u*cos(v)\ny = u*sin(v)\nz = v\n")  # the helicoid
    with pytest.raises(locus.InputError):
        locus.implicitize({"x": "t"})
    with pytest.raises(locus.InputError):
        locus.implicitize(ENNEPER, method="magic")
