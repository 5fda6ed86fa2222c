# The suite runs against the package in the build tree (CTest sets PYTHONPATH) or an installed
# one; LOCUS_SOURCE_DIR points at the repository's data.
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("LOCUS_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def source_dir():
    return SOURCE_DIR
