"""Shared by the module's tests: where the repository and the CLI are (ctest sets OASISC and
OASIS_SOURCE_DIR; run by hand, the default build is assumed)."""

import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("OASIS_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
OASISC = os.environ.get("OASISC", str(SOURCE_DIR / "build" / "default" / "compiler" / "oasisc"))
PRISM_DATA = SOURCE_DIR / "tests" / "data" / "prism"


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def oasisc():
    return OASISC
