# Rendering and tracing from Python: NumPy images that Jupyter can show, and first hits along
# random rays checked against the quadratic formula for a sphere (no locus code involved).
import math
import random
import zlib

import pytest

np = pytest.importorskip("numpy")
import locus


def test_render_is_an_image_with_depth_and_png():
    image = locus.render("x^4 + y^4 + z^4 - 1", size=(96, 64))
    assert image.shape == (64, 96, 3) and image.dtype == np.uint8
    assert image.stats["hits"] > 500 and image.stats["undecided"] == 0
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 20  # shaded, not flat
    assert np.isinf(image.depth[0, 0]) and np.isfinite(image.depth[32, 48])
    # The float AOVs: unit normals where the surface is hit, zero elsewhere; work where hit.
    lengths = np.linalg.norm(image.normal, axis=2)
    hit = np.isfinite(image.depth)
    assert np.allclose(lengths[hit], 1.0, atol=1e-4) and (lengths[~hit] == 0).all()
    assert image.linear.dtype == np.float32 and image.linear.shape == (64, 96, 3)
    assert (image.work[hit] > 0).all()
    png = image._repr_png_()
    assert png.startswith(b"\x89PNG\r\n\x1a\n")
    # The IDAT stream decodes back to the same rows (filter byte 0 each).
    start = png.index(b"IDAT") + 4
    length = int.from_bytes(png[start - 8:start - 4], "big")
    raw = zlib.decompress(png[start:start + length])
    rows = np.frombuffer(raw, dtype=np.uint8).reshape(64, 96 * 3 + 1)
    assert (rows[:, 0] == 0).all()
    assert (rows[:, 1:].reshape(64, 96, 3) == image).all()


def test_camera_and_methods():
    sphere = "x^2 + y^2 + z^2 - 1"
    front = locus.render(sphere, size=(48, 48), eye=(0, 0, 5), target=(0, 0, 0), up=(0, 1, 0),
                         fov=30)
    assert front.stats["camera"]["eye"] == (0.0, 0.0, 5.0)
    for method in locus.TRACE_METHODS:
        other = locus.render(sphere, size=(48, 48), eye=(0, 0, 5), fov=30, method=method)
        hit_here = np.isfinite(front.depth)
        hit_there = np.isfinite(other.depth)
        assert (hit_here != hit_there).sum() <= 4, method  # silhouette pixels at most
    with pytest.raises(locus.InputError):
        locus.render(sphere, size=(48, 48), eye=(0, 0, 0), target=(0, 0, 0))
    with pytest.raises(locus.ParseError) as caught:
        locus.render("x^2 + * 1", size=(8, 8))
    assert caught.value.column == 7
    with pytest.raises(locus.Error):
        locus.render(sphere, method="guess")
    # Review regressions: these were raised on the worker thread without the GIL (a crash).
    for bad in ({"size": (0, 4)}, {"size": (8, 8), "samples": 99}, {"size": (8, 8), "eye": (1, 2)}):
        with pytest.raises(locus.InputError):
            locus.render(sphere, **bad)


def test_scene_file(source_dir):
    scenes = sorted((source_dir / "docs/scenes").glob("*.toml"))
    if not scenes:
        pytest.skip("no scene files")
    image = locus.render(str(scenes[0]), size=(32, 24))
    assert image.shape == (24, 32, 3)


def test_an_equation_far_from_the_origin_is_the_same_picture_by_every_method(tmp_path):
    # Expanded at the origin its terms are 1e16 times its values: sturm drew 854 hits of 368.
    scene = tmp_path / "far.toml"
    scene.write_text('[[surface]]\nequation = "(x-1e8)^2+y^2+z^2-1"\nclip = "sphere"\n'
                     "clip_center = [1e8, 0, 0]\nclip_radius = 2\n")
    certified = locus.render(str(scene), size=(48, 48), method="certified")
    sturm = locus.render(str(scene), size=(48, 48), method="sturm")
    background = np.asarray(certified)[0, 0].astype(int)
    lit = (np.abs(np.asarray(certified).astype(int) - background).sum(axis=2) > 0).sum()
    assert 300 < lit < 450
    assert (np.asarray(certified) == np.asarray(sturm)).all()


def test_trace_against_the_quadratic_formula():
    rng = random.Random(11)
    origins, directions, expected = [], [], []
    for _ in range(400):
        o = [rng.uniform(-4, 4) for _ in range(3)]
        d = [rng.gauss(0, 1) for _ in range(3)]
        a = sum(c * c for c in d)
        b = 2 * sum(p * q for p, q in zip(o, d))
        c = sum(p * p for p in o) - 1
        disc = b * b - 4 * a * c
        roots = []
        if disc >= 0:
            roots = sorted(((-b - math.sqrt(disc)) / (2 * a), (-b + math.sqrt(disc)) / (2 * a)))
        hits = [t for t in roots if 0 < t <= 100]
        origins.append(o)
        directions.append(d)
        expected.append(hits[0] if hits else math.nan)
    for method in ("certified", "sturm", "exact"):
        t, status = locus.trace("x^2+y^2+z^2-1", origins, directions, method=method,
                                status=True)
        assert (status >= 0).all()
        expected_array = np.array(expected)
        assert (np.isnan(t) == np.isnan(expected_array)).all(), method
        both = ~np.isnan(expected_array)
        assert np.allclose(t[both], expected_array[both], rtol=1e-7, atol=1e-9), method


def test_trace_shapes_and_errors():
    t = locus.trace("z", [0, 0, 1], [0, 0, -1])
    assert t.shape == (1,) and t[0] == pytest.approx(1.0)
    with pytest.raises(locus.InputError):
        locus.trace("z", [[0, 0, 1]], [[0, 0, -1], [0, 0, 1]])
    with pytest.raises(locus.InputError):
        locus.trace("z", [[0, 0, 1]], [[0, 0, -1]], t_max=-1)
