"""The validation's whole-array test for a value twice in a face (a vertex, or a
neighbouring face), against a plain check of every face."""

from __future__ import annotations

import types

import numpy as np
import pytest

from pentanb.mesh import validate


def brute(values: np.ndarray, k: int) -> bool:
    rows = np.sort(values.reshape(-1, k), axis=1)  # equal values side by side
    return bool((rows[:, 1:] == rows[:, :-1]).any())


@pytest.mark.parametrize("k", [3, 4, 5, 8, 16])
def test_every_pair_of_corners_in_every_block_is_compared(k):
    rows = validate._ROWS // k
    m = 2 * rows + 7  # three blocks, the last one short
    mesh = types.SimpleNamespace(_uniform_size=k)
    base = np.arange(m * k, dtype=np.int32)
    assert not validate._repeats_in_a_face(mesh, base, base.size)
    for r in (0, rows - 1, rows, m - 1):
        for i in range(k):
            for j in range(i + 1, k):
                values = base.copy()
                values[r * k + j] = values[r * k + i]
                assert brute(values, k)
                assert validate._repeats_in_a_face(mesh, values, base.size), (r, i, j)
    # a value repeated across two faces is no repeat
    values = base.copy()
    values[k] = values[k - 1]
    assert not brute(values, k)
    assert not validate._repeats_in_a_face(mesh, values, base.size)
