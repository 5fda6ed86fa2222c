# Every example of docs/python.md runs as a doctest, from the source root (its paths are
# relative to it), so that the page shows what the package does.
import doctest
import os

import pytest


def test_python_guide_examples(source_dir, monkeypatch):
    pytest.importorskip("numpy")
    monkeypatch.chdir(source_dir)
    failures, tried = doctest.testfile(str(source_dir / "docs/python.md"), module_relative=False,
                                       optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert tried >= 15
    assert failures == 0
