"""The corpus of test meshes: every shape of :data:`pentanb.shapes.SHAPES` plus
a few mixed-face meshes (see :mod:`helpers`), and the operators under test."""

from __future__ import annotations

import os
import sys

import pytest
from hypothesis import settings

sys.path.insert(0, os.path.dirname(__file__))

# Under CI the property tests draw the same examples on every run (a failure
# there is reproducible, never luck); elsewhere they explore new ones.
settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

from helpers import CORPUS_NAMES, OPERATORS, SMALL_NAMES, corpus  # noqa: E402


@pytest.fixture(params=CORPUS_NAMES)
def corpus_name(request) -> str:
    """The name of a corpus mesh (every shape and every mixed mesh)."""
    return request.param


@pytest.fixture
def corpus_mesh(corpus_name):
    """A corpus mesh (built once per session: meshes are immutable)."""
    return corpus(corpus_name)


@pytest.fixture(params=SMALL_NAMES)
def small_mesh(request):
    """A small corpus mesh, for the pure-Python isomorphism checks."""
    return corpus(request.param)


@pytest.fixture(params=list(OPERATORS))
def operator_name(request) -> str:
    """Every registered scheme and ``dual``."""
    return request.param
