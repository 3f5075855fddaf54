"""Shared by the Python package's tests: where the sources and the programs are (ctest's environment:
tests/python/CMakeLists.txt)."""
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("WTC_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def wtc_sim():
    path = os.environ.get("WTC_SIM")
    if not path:
        pytest.fail("WTC_SIM is not set (run the tests through ctest)")
    return path
