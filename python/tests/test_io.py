"""read_mesh / write_mesh / read_points: round trips through every writable format, welding."""
import numpy as np
import pytest

import gsp
from conftest import grid, shared_mesh


@pytest.mark.parametrize("ext", ["ply", "obj", "off", "gltf", "glb"])
def test_round_trip(ext, tmp_path):
    V, F = grid(6, jitter=0.2)
    values = np.linalg.norm(V, axis=1)
    out = tmp_path / f"mesh.{ext}"
    gsp.write_mesh(out, V, F, values)
    V2, F2 = gsp.read_mesh(out, weld=False)
    assert V2.dtype == np.float64 and F2.dtype == np.int64
    np.testing.assert_array_equal(F2, F)
    # glTF stores float32 positions; the text formats enough digits for float32 at least.
    np.testing.assert_allclose(V2, V, rtol=0, atol=1e-6)


def test_values_txt_and_labels(tmp_path):
    V, F = grid(5)
    values = np.arange(len(V), dtype=float)
    values[3] = np.inf
    gsp.write_mesh(tmp_path / "v.txt", V, F, values)
    back = np.loadtxt(tmp_path / "v.txt")
    assert back[3] == np.inf and back[4] == 4
    gsp.write_mesh(tmp_path / "l.ply", V, F, values, labels=np.arange(len(V)) % 3, ascii=True)
    text = (tmp_path / "l.ply").read_text()
    assert "property float distance" in text and "property int label" in text and "property uchar red" in text


def test_stl_is_welded_like_the_apps():
    path = shared_mesh("thingi10k_99865_tires.stl")
    V, F = gsp.read_mesh(path)
    Vraw, Fraw = gsp.read_mesh(path, weld=False)
    assert len(Vraw) == 3 * len(Fraw) and len(V) < len(Vraw)
    assert len(F) == len(Fraw)
    np.testing.assert_allclose(V[F], Vraw[Fraw])


def test_read_points(tmp_path):
    P = gsp.read_points(shared_mesh("kitten_points.xyz"))
    assert P.ndim == 2 and P.shape[1] == 3 and len(P) > 1000
    V, F = grid(4)
    gsp.write_mesh(tmp_path / "g.obj", V, F)
    P2, N2 = gsp.read_points(tmp_path / "g.obj", normals=True)
    np.testing.assert_allclose(P2, V, atol=1e-9)
    assert N2.shape == P2.shape


def test_read_errors(tmp_path):
    with pytest.raises(OSError, match="missing.obj"):
        gsp.read_mesh(tmp_path / "missing.obj")
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(OSError, match="bad.off"):
        gsp.read_mesh(bad)
    nan = tmp_path / "nan.obj"
    nan.write_text("v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(OSError):
        gsp.read_mesh(nan)
    cloud = tmp_path / "cloud.xyz"
    cloud.write_text("0 0 0\n1 0 0\n")
    with pytest.raises(OSError, match="no faces"):
        gsp.read_mesh(cloud)
    with pytest.raises(OSError):
        gsp.read_mesh(tmp_path / "x.unknown")


def test_write_errors(tmp_path):
    V, F = grid(3)
    with pytest.raises(OSError):
        gsp.write_mesh(tmp_path / "out.stl", V, F)
    with pytest.raises(OSError):
        gsp.write_mesh(tmp_path / "no" / "such" / "dir.ply", V, F)
    with pytest.raises(ValueError, match="values"):
        gsp.write_mesh(tmp_path / "a.ply", V, F, np.zeros(len(V) + 1))
    with pytest.raises(ValueError, match="colormap"):
        gsp.write_mesh(tmp_path / "a.ply", V, F, np.zeros(len(V)), colormap="jet")
    assert not list(tmp_path.iterdir())   # nothing half-written
