"""Hostile input: each case runs in its own process, with a memory limit, and must end in
a clear error (never a crash of the interpreter, a hang or a wrong result)."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

#: Each case's own process gets this address space (bytes), and this many seconds: a
#: guard against a hang, far above what a case takes on a busy machine.
MEMORY = 4 << 30
SECONDS = 900

PRELUDE = """
import pickle, resource, numpy as np, pentanb as pb
resource.setrlimit(resource.RLIMIT_AS, ({memory}, {memory}))
pb.use_jit({jit})
pb._jit.MIN_CORNERS = 0  # the compiled kernels (when on) on meshes of any size
"""


def run_case(body: str, jit: bool) -> subprocess.CompletedProcess:
    code = PRELUDE.format(memory=MEMORY, jit=jit) + textwrap.dedent(body)
    return subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=SECONDS
    )


def paths() -> list:
    try:
        import numba  # noqa: F401
    except ImportError:
        return [False]
    return [False, True]


TORUS = "b = pb.shapes.torus(32, 16)\n"

#: name -> code that must raise pentanb.MeshError (and print its message).
CASES = {
    "scrambled twins": TORUS + "pb.Mesh.from_csr(b.vertices, b.corners, b.offsets,"
    " twin=np.random.default_rng(0).permutation(b.n_halfedges), validate=False)",
    "twins out of range": TORUS + "pb.Mesh.from_csr(b.vertices, b.corners, b.offsets,"
    " twin=np.full(b.n_halfedges, 10**6), validate=False)",
    "falling offsets": TORUS
    + "o = b.offsets.copy(); o[5], o[6] = o[6], o[5]\n"
    + "pb.Mesh.from_csr(b.vertices, b.corners, o, validate=False)",
    "a NaN vertex unchecked": TORUS
    + "v = b.vertices.copy(); v[3, 1] = np.nan\n"
    + "pb.Mesh.from_csr(v, b.corners, b.offsets, validate=False)",
    "a tampered corner in a pickle": TORUS
    + "data = bytearray(pickle.dumps(b))\n"
    + "i = bytes(data).find(b.corners.tobytes()[400:440]) + 0\n"
    + "data[i:i + b.corners.itemsize] = np.array(10**9, b.corners.dtype).tobytes()\n"
    + "pb.dual(pickle.loads(bytes(data)))",
    "tampered twins in a pickle": TORUS
    + "t = b.twin\n"
    + "data = bytearray(pickle.dumps(b))\n"
    + "i = bytes(data).find(t.tobytes())\n"
    + "data[i:i + t.nbytes] = np.roll(t, 1).tobytes()\n"
    + "pb.preserve_pentagons(pickle.loads(bytes(data)))",
    "tampered rings in a pickle": TORUS
    + "r, _ = b.vertex_ring\n"
    + "data = bytearray(pickle.dumps(b))\n"
    + "i = bytes(data).find(r.tobytes())\n"
    + "data[i:i + r.nbytes] = np.roll(r, 1).tobytes()\n"
    + "pb.pentagonalize(pickle.loads(bytes(data)))",
}


@pytest.mark.slow
@pytest.mark.parametrize("jit", paths(), ids=lambda j: "compiled" if j else "numpy")
@pytest.mark.parametrize("name", sorted(CASES))
def test_bad_arrays_are_a_mesh_error_on_both_paths(name, jit):
    body = f"try:\n{textwrap.indent(CASES[name], '    ')}\nexcept pb.MeshError as e:\n"
    body += "    print('MeshError:', e)\nelse:\n    print('accepted')\n"
    done = run_case(body, jit)
    assert done.returncode == 0, done.stderr[-2000:]  # a signal gives a negative code
    assert done.stdout.startswith("MeshError:"), done.stdout + done.stderr[-2000:]


@pytest.mark.slow
def test_the_harness_sees_a_crash_and_an_accepted_input():
    crash = run_case("import os, signal; os.kill(os.getpid(), signal.SIGSEGV)", False)
    assert crash.returncode < 0
    fine = run_case("print('accepted' if pb.shapes.cube() else '')", False)
    assert fine.stdout.strip() == "accepted"
