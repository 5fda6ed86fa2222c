"""locus: exact Gröbner bases and implicit equations, and certified ray tracing of algebraic surfaces.

    >>> import locus
    >>> print(locus.groebner(['x^2+y', 'y^2-1'], vars='x,y', order='lex'))
    y^2-1
    x^2+y

Polynomials have exact rational coefficients (FLINT); every long call releases the GIL, takes a
``timeout=`` in seconds, and stops within a fraction of a second on Ctrl-C (KeyboardInterrupt).
Errors are ``locus.ParseError`` (with ``.line`` and ``.column``), ``locus.InputError``,
``locus.Timeout``, ``locus.ResourceError`` and ``locus.VerificationError``, all ``locus.Error``.
See docs/user-guide.md, "Python".
"""

import os as _os
import struct as _struct
import warnings as _warnings
import zlib as _zlib

from . import _locus
from ._locus import (Error, InputError, ParseError, Polynomial, ResourceError, Ring, Timeout,
                     VerificationError)

__all__ = [
    "Ring", "Polynomial", "Basis", "Ideal", "read_ideal", "groebner", "reduce", "divide", "verify", "ideal",
    "implicitize", "Implicit", "render", "Image", "trace", "to_sympy", "from_sympy",
    "Error", "ParseError", "InputError", "Timeout", "ResourceError", "VerificationError",
    "FORMATS", "TRACE_METHODS",
]

# Jupyter shows polynomials as LaTeX.
Polynomial._repr_latex_ = lambda self: "$%s$" % self.format("latex")

FORMATS = ("normalized", "singular", "macaulay2", "latex", "msolve", "sympy", "maple",
           "mathematica")
TRACE_METHODS = tuple(_locus._trace_methods())


def _polynomials(polys, vars=None, order=None):
    """Polynomials of one ring from polynomials, or from strings (and numbers) with `vars`."""
    polys = list(polys)
    ring = None
    if vars is not None:
        ring = Ring(vars, order or "grevlex")
    else:
        rings = [p.ring for p in polys if isinstance(p, Polynomial)]
        if not rings:
            raise InputError("give vars= (e.g. vars='x,y,z') for polynomials written as strings")
        ring = rings[0]
        if order is not None:
            ring = ring.with_order(order)
    out = []
    for p in polys:
        if isinstance(p, Polynomial):
            out.append(p if p.ring == ring else p.in_ring(ring))
        else:
            out.append(ring(p))
    return ring, out


class Basis(list):
    """A reduced Gröbner basis: a list of polynomials, leading monomials ascending.

    ``str`` gives the normalized form (one polynomial a line, as ``locus groebner`` prints it);
    ``.format('singular')`` and the other FORMATS give input for those systems. ``.stats`` says
    which algorithm answered, whether the basis is certified, and what it cost.
    """

    def __init__(self, polys, ring, characteristic=0, stats=None):
        super().__init__(polys)
        self.ring = ring
        self.characteristic = characteristic
        self.stats = dict(stats or {})

    def format(self, format="normalized"):
        return _locus._format(list(self), self.ring, format, self.characteristic)

    def __str__(self):
        return self.format("normalized").rstrip("\n")

    def __repr__(self):
        return "Basis([%s], ring=%r)" % (", ".join(repr(str(p)) for p in self), self.ring)

    def _repr_latex_(self):
        return "$\\begin{aligned}%s\\end{aligned}$" % " \\\\ ".join(
            p.format("latex") for p in self)


def groebner(polys, vars=None, order=None, algorithm="auto", certify=True, timeout=None,
             characteristic=0, check=False, threads=1):
    """The reduced Gröbner basis of the ideal the polynomials generate.

    polys: ring polynomials, strings together with ``vars`` ('x,y,z' or a list, in order), or
        an Ideal (read_ideal), whose characteristic is used.
    order: lex, grlex, grevlex (default), weights(...), elim(...), matrix(...).
    algorithm: auto, buchberger, signature, modular (over GF(p): auto or modular, F4 modulo p).
    certify: over Q, the modular algorithm's lift is certified exactly (False: probabilistic).
    characteristic: 0 for Q, or a prime p < 2^31 for GF(p) (coefficients then in [0, p)).
    check: verify the answer independently (S-pairs and generators reduce to zero, reduced);
        a failure raises VerificationError.
    threads: the signature algorithm attempts the signatures of a degree side by side, the
        modular one runs its primes and certification on this many threads; the basis is the
        same on any number.
    """
    if isinstance(polys, Ideal):
        if characteristic == 0:
            characteristic = polys.characteristic
        elif polys.characteristic not in (0, characteristic):
            raise InputError("characteristic %d: the ideal has characteristic %d"
                             % (characteristic, polys.characteristic))
        polys = polys.generators
    ring, gens = _polynomials(polys, vars, order)
    basis, stats = _locus._groebner(gens, algorithm, certify, timeout, int(characteristic),
                                    int(threads), check)
    return Basis(basis, ring, int(characteristic), stats)


class Ideal:
    """Generators read from an ideal file or msolve's format: ``.generators``, ``.ring``,
    ``.characteristic`` (0 for Q). ``groebner(ideal)`` computes in its ring and characteristic."""

    def __init__(self, ring, generators, characteristic):
        self.ring = ring
        self.generators = list(generators)
        self.characteristic = characteristic

    def __iter__(self):
        return iter(self.generators)

    def __len__(self):
        return len(self.generators)

    def __repr__(self):
        return "Ideal(%d generators, %r, characteristic=%d)" % (
            len(self.generators), self.ring, self.characteristic)


def read_ideal(source):
    """An Ideal from a file path or from the text itself: an ideal file, msolve's format (.ms),
    or a pasted Singular (``ring r = 0, (x,y), dp; ideal I = ...;``) or Macaulay2
    (``R = QQ[x,y]; I = ideal(...)``) session, told apart by content."""
    text = str(source)
    path = None
    if "\n" not in text and _os.path.exists(text):
        path = text
        with open(path, encoding="utf-8") as f:
            text = f.read()
    return Ideal(*_locus._read_ideal(text, bool(path and path.endswith(".ms"))))


def verify(basis, generators, characteristic=None):
    """(ok, why): is ``basis`` a reduced Gröbner basis, and do ``generators`` reduce to zero by it?
    Over GF(p) for a Basis computed there (or with ``characteristic=p``)."""
    if characteristic is None:
        characteristic = getattr(basis, "characteristic", 0)
    ring, polys = _polynomials(list(basis) + list(generators))
    n = len(basis)
    ok, why = _locus._verify(polys[:n], polys[n:], int(characteristic))
    return ok and not why, why


def reduce(f, basis, vars=None, order=None):
    """The normal form (remainder) of f by the polynomials of ``basis``, over Q."""
    ring, polys = _polynomials([f] + list(basis), vars, order)
    return _locus._normal_form(polys[0], polys[1:])


def divide(f, divisors, vars=None, order=None):
    """(quotients, remainder) with f = sum(q * g) + remainder, by the division algorithm."""
    ring, polys = _polynomials([f] + list(divisors), vars, order)
    return _locus._divide(polys[0], polys[1:])


class _IdealOperations:
    """Operations on ideals given by generators (ring polynomials, or strings with ``vars``).

    Each returns a Basis (reduced, under the ring's order) or an answer, and takes
    ``timeout=`` in seconds.
    """

    @staticmethod
    def _two(i, j, vars, order):
        ring, polys = _polynomials(list(i) + list(j), vars, order)
        return ring, polys[:len(i)], polys[len(i):]

    def _basis_of_two(operation, doc):
        def method(self, i, j, vars=None, order=None, timeout=None):
            ring, a, b = self._two(i, j, vars, order)
            return Basis(operation(a, b, timeout), ring)
        method.__doc__ = doc
        return method

    sum = _basis_of_two(_locus._ideal_sum, "I + J")
    product = _basis_of_two(_locus._ideal_product, "I·J")
    intersect = _basis_of_two(_locus._ideal_intersection, "I ∩ J")
    quotient = _basis_of_two(_locus._ideal_quotient, "I : J")
    saturate = _basis_of_two(_locus._saturation, "I : J^∞")
    del _basis_of_two

    def eliminate(self, i, variables, vars=None, order=None, timeout=None):
        """I ∩ Q[the other variables]; ``variables``: names ('t' or ['s', 't']) or polynomials."""
        ring, polys = _polynomials(i, vars, order)
        if isinstance(variables, str):
            variables = [v.strip() for v in variables.split(",")]
        return Basis(_locus._eliminate(polys, list(variables), timeout), ring)

    def contains(self, i, j, vars=None, order=None, timeout=None):
        """Is J ⊆ I (each generator of J in I)?"""
        ring, a, b = self._two(i, j, vars, order)
        return _locus._contains(a, b, timeout)

    def equal(self, i, j, vars=None, order=None, timeout=None):
        ring, a, b = self._two(i, j, vars, order)
        return _locus._equal(a, b, timeout)

    def member(self, f, i, vars=None, order=None, timeout=None):
        """(is_member, cofactors, remainder): f = sum(c * g) exactly when a member (checked)."""
        ring, polys = _polynomials([f] + list(i), vars, order)
        return _locus._member(polys[0], polys[1:], timeout)

    def radical_member(self, f, i, vars=None, order=None, timeout=None):
        """Is f in the radical of I (does a power of f lie in I)?"""
        ring, polys = _polynomials([f] + list(i), vars, order)
        return _locus._radical_member(polys[0], polys[1:], timeout)

    def dimension(self, i, vars=None, order=None, timeout=None):
        """Krull dimension and what goes with it, as a dict: 'kind' ('unit', 'zero-dimensional'
        or 'positive-dimensional'), 'dimension' (-1 for the unit ideal), 'degree', 'solutions'
        (for zero-dimensional ideals: their number with multiplicity, else None),
        'hilbert_series' (Q with HS = Q(t)/(1-t)^dimension, coefficients from t^0),
        'hilbert_polynomial' (coefficients from s^0, as Fractions), 'regularity' (HF = HP from
        there on) and 'independent_set' (variable names). ``i`` may be empty: the zero ideal."""
        ring, polys = _polynomials(i, vars, order) if vars is not None or len(i) else (None, [])
        if ring is None:
            raise InputError("dimension: give vars= for the zero ideal")
        return _locus._dimension(ring, polys, timeout)


ideal = _IdealOperations()


class Implicit:
    """The result of implicitize: ``equation`` (a Polynomial in x, y(, z), primitive, verified by
    substitution), or for images that are not hypersurfaces ``generators`` and ``image``."""

    def __init__(self, fields):
        self.ring = fields["ring"]
        self.equation = fields["equation"]
        self.generators = Basis(fields["generators"], fields["ring"])
        self.image = fields["image"]
        self.description = fields["description"]
        self.method = fields["method"]
        self.fallback_reason = fields["fallback_reason"]
        self.angles = list(fields["angles"])
        self.verified = True  # the bindings raise VerificationError otherwise

    def __str__(self):
        return str(self.equation) if self.equation is not None else str(self.generators)

    def __repr__(self):
        return "Implicit(%r, method=%r)" % (str(self), self.method)

    def _repr_latex_(self):
        if self.equation is None:
            return self.generators._repr_latex_()
        return "$%s = 0$" % self.equation.format("latex")


def _param_text(param):
    if isinstance(param, dict):
        lines = []
        params = param.get("params")
        if params is None:
            raise InputError("implicitize: the dictionary needs 'params' (e.g. 's,t')")
        if not isinstance(params, str):
            params = ",".join(params)
        lines.append("params: " + params)
        for key in ("x", "y", "z"):
            if key in param:
                lines.append("%s = %s" % (key, param[key]))
        if "domain" in param:
            lines.append("domain: " + param["domain"])
        unknown = set(param) - {"params", "x", "y", "z", "domain"}
        if unknown:
            raise InputError("implicitize: unknown keys %s (expected params, x, y, z, domain)"
                             % ", ".join(sorted(unknown)))
        return "\n".join(lines) + "\n"
    text = str(param)
    if "\n" not in text and text.endswith(".param") and _os.path.exists(text):
        with open(text, encoding="utf-8") as f:
            return f.read()
    return text


def implicitize(param, method="auto", timeout=None, threads=1):
    """The implicit equation of a parametrization, verified by substitution.

    param: the text of a .param file ('params: s,t\\nx = ...'), a path to one, or a dict
        {'params': 's,t', 'x': '...', 'y': '...', 'z': '...'}; sin and cos of the parameters
        are allowed (angles).
    method: auto, groebner, resultant, interpolate, dixon.
    """
    return Implicit(_locus._implicitize(_param_text(param), method, timeout, int(threads)))


def _png(rgb):
    """PNG bytes of an H×W×3 uint8 array (zlib from the standard library; no PIL needed)."""
    height, width = rgb.shape[0], rgb.shape[1]
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(height))

    def chunk(tag, data):
        return (_struct.pack(">I", len(data)) + tag + data +
                _struct.pack(">I", _zlib.crc32(tag + data) & 0xFFFFFFFF))

    return (b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", _struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", _zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def _image_class():
    import numpy

    class Image(numpy.ndarray):
        """An H×W×3 uint8 sRGB picture (a NumPy array) that Jupyter shows inline. The float
        AOVs of ``locus render --aov``: ``.depth`` (H×W, the distance to the first hit, inf on a
        miss), ``.normal`` (H×W×3 unit normals, zero on a miss), ``.work`` (H×W, the root
        finders' work per pixel) and ``.linear`` (H×W×3 linear colour before sRGB); ``.stats``
        the frame's figures (seconds, rays, hits, undecided rays, the camera used)."""

        def _repr_png_(self):
            return _png(numpy.ascontiguousarray(self, dtype=numpy.uint8))

        def save(self, path):
            """Writes the picture as PNG."""
            with open(path, "wb") as f:
                f.write(self._repr_png_())

        def __array_finalize__(self, obj):
            for name in ("depth", "normal", "work", "linear", "stats"):
                setattr(self, name, getattr(obj, name, None))

    return Image


Image = None  # set on first use of render(), so that importing locus does not need NumPy


def _source_kind(source):
    text = str(source)
    if "\n" not in text and _os.path.exists(text):
        if text.endswith(".toml"):
            return "scene"
        if text.endswith((".param", ".bpt")):
            return "param"
    return "equation"


def render(source, size=(512, 512), eye=None, target=None, up=None, fov=None, method=None,
           samples=None, shadows=None, threads=0, timeout=None):
    """Ray-traces a surface to an Image (H×W×3 uint8 NumPy array, shown inline in Jupyter).

    source: an equation in x, y, z ('x^2+y^2+z^2-1'), or the path of a scene file (.toml), a
        parametrization (.param) or Bézier patches (.bpt), as ``locus render`` takes them.
    size: (width, height). eye, target, up: 3-sequences; fov in degrees; without them the
        camera frames the surface. method: one of TRACE_METHODS (default certified).
    """
    global Image
    if Image is None:
        Image = _image_class()
    width, height = size
    vec = lambda v: None if v is None else [float(c) for c in v]
    rgb, depth, stats, aovs = _locus._render(str(source), _source_kind(source), int(width),
                                             int(height), vec(eye), vec(target), vec(up), fov,
                                             method, samples, shadows, int(threads), timeout)
    image = rgb.view(Image)
    image.depth = depth
    image.linear = aovs["linear"]
    image.normal = aovs["normal"]
    image.work = aovs["work"]
    image.stats = stats
    return image


def trace(equation, origins, directions, method="certified", t_max=100.0, timeout=None,
          status=False):
    """First hits of the rays o + t·d with the surface, t in (0, t_max], vectorised.

    origins, directions: arrays of shape (N, 3) (or one ray of shape (3,)). Returns the t
    values (NaN for a miss); with ``status=True`` also an int8 array: 1 hit, 0 miss, -1 the
    method could not decide (then t is NaN too, and without status= a warning says how many).
    """
    import numpy
    o = numpy.atleast_2d(numpy.asarray(origins, dtype=float))
    d = numpy.atleast_2d(numpy.asarray(directions, dtype=float))
    t, codes = _locus._trace(equation, o, d, method, float(t_max), timeout)
    if status:
        return t, codes
    undecided = int((codes < 0).sum())
    if undecided:
        _warnings.warn("trace: %d of %d rays were undecided by method %s (NaN); pass "
                       "status=True to tell them from misses" % (undecided, len(codes), method),
                       RuntimeWarning, stacklevel=2)
    return t


def to_sympy(poly):
    """A SymPy expression equal to the polynomial (needs SymPy)."""
    import sympy
    names = poly.ring.variables
    symbols = dict(zip(names, sympy.symbols(names)))
    return sympy.sympify(str(poly).replace("^", "**"), locals=symbols)


def from_sympy(expr, ring):
    """The polynomial of ``ring`` equal to a SymPy expression (exact rational coefficients)."""
    import sympy
    expanded = sympy.expand(sympy.sympify(expr))
    return ring(sympy.sstr(expanded, order="none").replace("**", "^"))
