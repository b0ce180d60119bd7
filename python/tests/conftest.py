# SPDX-License-Identifier: MIT
import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("CGOGN_DATA_DIR", ROOT / "tests" / "data"))
BAD = ROOT / "tests" / "io" / "bad"


@pytest.fixture
def data():
    return DATA


def read_off(path):
    """An independent OFF reader: (points, faces as lists)."""
    words = []
    for line in open(path):
        line = line.split("#")[0]
        words.extend(line.split())
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    k = 4
    points = [[float(w) for w in words[k + 3 * i : k + 3 * i + 3]] for i in range(nv)]
    k += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[k])
        faces.append([int(w) for w in words[k + 1 : k + 1 + n]])
        k += 1 + n
    return points, faces
