#!/usr/bin/env python3
"""Writes the binary and generated fixtures of tests/data/io (run from anywhere; idempotent).
The text fixtures next to this script are written by hand; the expected values are in
tests/io_read_fixtures.cpp and tests/io_broken_files.cpp."""
import base64, json, os, struct

HERE = os.path.dirname(os.path.abspath(__file__))
BROKEN = os.path.join(HERE, "broken")


def write(name, data, folder=HERE):
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


# --- PLY, big-endian: double coordinates, normals, an extra float, a vertex list property,
# an extra element before the faces, face lists with uchar and ushort counts and ushort/uint
# indices, a quad, and an extra list property after the index list.
def ply_big_endian():
    verts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, 1)]
    h = ("ply\nformat binary_big_endian 1.0\ncomment extra properties everywhere\n"
         "element vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
         "property float nx\nproperty float ny\nproperty float nz\n"
         "property list uchar int vertex_junk\nproperty float quality\n"
         "element material 2\nproperty uchar r\nproperty list uint short stuff\n"
         "element face 3\nproperty uchar flags\nproperty list ushort ushort vertex_indices\n"
         "property list uchar float texcoord\nproperty int tag\nend_header\n").encode()
    b = b""
    for i, (x, y, z) in enumerate(verts):
        b += struct.pack(">ddd", x, y, z) + struct.pack(">fff", 0, 0, 1)
        b += struct.pack(">B", i % 3) + struct.pack(">%di" % (i % 3), *range(i % 3))
        b += struct.pack(">f", 0.25 * i)
    b += struct.pack(">B", 7) + struct.pack(">I", 2) + struct.pack(">hh", -1, 2)
    b += struct.pack(">B", 8) + struct.pack(">I", 0)
    faces = [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4)]
    for k, f in enumerate(faces):
        b += struct.pack(">B", 1) + struct.pack(">H", len(f)) + struct.pack(">%dH" % len(f), *f)
        b += struct.pack(">B", 2) + struct.pack(">ff", 0.5, 0.5) + struct.pack(">i", -k)
    write("big_endian_extras.ply", h + b)


def ply_little_uchar_ushort():
    # uchar indices with a char count; ushort count with uint indices in a second face element
    # property layout: both decode to the same two triangles.
    h = ("ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
         "property float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
         "property uchar blue\nproperty int label\nelement face 2\n"
         "property list char uchar vertex_index\nend_header\n").encode()
    b = b""
    for i, p in enumerate([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]):
        b += struct.pack("<fff", *p) + bytes([10 * i, 20 * i, 30 * i]) + struct.pack("<i", 100 + i)
    b += struct.pack("<bBBB", 3, 0, 1, 2) + struct.pack("<bBBB", 3, 1, 3, 2)
    write("uchar_indices.ply", h + b)


def stl_binary_solid_header():
    # A binary STL whose 80-byte header starts with "solid": detected by its size.
    head = b"solid but binary".ljust(80, b" ")
    tris = [((0, 0, 1), (0, 0, 0), (1, 0, 0), (0, 1, 0)), ((0, 0, 1), (1, 0, 0), (1, 1, 0), (0, 1, 0))]
    b = head + struct.pack("<I", len(tris))
    for n, a, c, d in tris:
        b += struct.pack("<12f", *n, *a, *c, *d) + b"\0\0"
    write("solid_header_binary.stl", b)
    return b


def gltf_fixture():
    # Root node translated by (10,0,0) with a child scaled by 2 holding an indexed quad (2
    # triangles); a sibling rotated 90 degrees about z holding a non-indexed triangle, a strip
    # (4 vertices -> 2 triangles), a fan (5 vertices -> 3 triangles) and a LINES primitive
    # (skipped); a node outside the scene that must not be read.
    buf = b""
    views, accs = [], []

    def add(data, fmt, count, ctype, typ, target, minmax=None):
        nonlocal buf
        while len(buf) % 4:
            buf += b"\0"
        raw = struct.pack("<" + fmt, *data)
        views.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(raw), "target": target})
        buf += raw
        a = {"bufferView": len(views) - 1, "componentType": ctype, "count": count, "type": typ}
        if minmax:
            a["min"], a["max"] = minmax
        accs.append(a)
        return len(accs) - 1

    def pos(points):
        flat = [c for p in points for c in p]
        lo = [min(p[i] for p in points) for i in range(3)]
        hi = [max(p[i] for p in points) for i in range(3)]
        return add(flat, "%df" % len(flat), len(points), 5126, "VEC3", 34962, (lo, hi))

    quad = pos([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)])
    quad_idx = add([0, 1, 2, 0, 2, 3], "6H", 6, 5123, "SCALAR", 34963)
    tri = pos([(0, 0, 0), (1, 0, 0), (0, 1, 0)])
    strip = pos([(0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1)])
    fan = pos([(0, 0, 2), (1, 0, 2), (1, 1, 2), (0, 1, 2), (-1, 1, 2)])
    line = pos([(5, 5, 5), (6, 6, 6)])
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [
            {"translation": [10, 0, 0], "children": [1, 2]},
            {"scale": [2, 2, 2], "mesh": 0},
            {"rotation": [0, 0, 0.7071067811865476, 0.7071067811865476], "mesh": 1},
            {"mesh": 0, "translation": [100, 100, 100]},
        ],
        "meshes": [
            {"primitives": [{"attributes": {"POSITION": quad}, "indices": quad_idx}]},
            {"primitives": [{"attributes": {"POSITION": tri}},
                            {"attributes": {"POSITION": strip}, "mode": 5},
                            {"attributes": {"POSITION": fan}, "mode": 6},
                            {"attributes": {"POSITION": line}, "mode": 1}]},
        ],
        "buffers": [{"byteLength": len(buf),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
        "bufferViews": views,
        "accessors": accs,
    }
    write("scene_transforms.gltf", json.dumps(gltf, indent=1))

    # POINTS only: a point cloud.
    pts = {"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 0}]}],
           "buffers": gltf["buffers"], "bufferViews": views[:1], "accessors": accs[:1]}
    write("points_only.gltf", json.dumps(pts))

    # Broken: accessor 0 claims more elements than its buffer view holds; another file has an
    # index that points past the vertices.
    bad = json.loads(json.dumps(gltf))
    bad["accessors"][quad]["count"] = 1000
    write("accessor_overrun.gltf", json.dumps(bad), BROKEN)
    bad = json.loads(json.dumps(gltf))
    bad["accessors"][quad]["byteOffset"] = 2 ** 40
    write("accessor_offset.gltf", json.dumps(bad), BROKEN)
    bad = json.loads(json.dumps(gltf))
    bad["accessors"][quad]["componentType"] = 9999
    write("accessor_component.gltf", json.dumps(bad), BROKEN)
    bad = json.loads(json.dumps(gltf))
    bad["accessors"][quad_idx]["bufferView"] = 0    # reads the positions' floats as indices
    bad["accessors"][quad_idx]["count"] = 12   # element 7 holds the high half of 1.0f
    write("index_out_of_range.gltf", json.dumps(bad), BROKEN)
    bad = json.loads(json.dumps(gltf))
    bad["bufferViews"][0]["byteLength"] = 100000
    write("bufferview_overrun.gltf", json.dumps(bad), BROKEN)
    return gltf, buf


def glb(gltf, buf):
    j = dict(gltf)
    j["buffers"] = [{"byteLength": len(buf)}]
    js = json.dumps(j).encode()
    while len(js) % 4:
        js += b" "
    while len(buf) % 4:
        buf += b"\0"
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(buf), 0x004E4942) + buf
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def broken(stl_bytes, glb_bytes):
    for ext in ["obj", "ply", "off", "stl", "gltf", "glb", "xyz"]:
        write("empty." + ext, b"", BROKEN)
    write("wrong_magic.ply", "plx\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n", BROKEN)
    write("wrong_magic.off", "FOO\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", BROKEN)
    write("wrong_magic.glb", b"glTx" + glb_bytes[4:], BROKEN)
    write("glb_version1.glb", glb_bytes[:4] + struct.pack("<I", 1) + glb_bytes[8:], BROKEN)
    write("truncated.glb", glb_bytes[:len(glb_bytes) // 2], BROKEN)
    write("truncated_json_chunk.glb", glb_bytes[:12] + struct.pack("<I", 0xFFFFFFF0) + glb_bytes[16:], BROKEN)
    write("truncated.stl", stl_bytes[:-30], BROKEN)
    write("tiny.stl", b"\0" * 40, BROKEN)
    write("absurd_count.stl", stl_bytes[:80] + struct.pack("<I", 4000000000) + stl_bytes[84:], BROKEN)
    ply = open(os.path.join(HERE, "big_endian_extras.ply"), "rb").read()
    write("truncated_binary.ply", ply[:-10], BROKEN)
    write("absurd_count.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
          "property float x\nproperty float y\nproperty float z\nend_header\n" + "\0" * 24, BROKEN)
    write("absurd_list.ply", b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
          b"property float y\nproperty float z\nelement face 1\nproperty list uint int vertex_indices\n"
          b"end_header\n" + b"\0" * 36 + struct.pack("<I", 4000000000) + b"\0" * 8, BROKEN)
    write("index_out_of_range.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
          "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", BROKEN)
    write("negative_index.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
          "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", BROKEN)
    write("nan_vertex.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
          "property float y\nproperty float z\nend_header\n0 0 0\n1 nan 0\n0 1 0\n", BROKEN)
    write("no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", BROKEN)
    write("nan_vertex.obj", "v 0 0 0\nv 1 0 0\nv 0 NaN 0\nf 1 2 3\n", BROKEN)
    write("inf_vertex.xyz", "0 0 0\n1 inf 0\n", BROKEN)
    write("index_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", BROKEN)
    write("negative_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", BROKEN)
    write("zero_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", BROKEN)
    write("two_corners.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", BROKEN)
    write("garbage.obj", "this is not an obj file\n", BROKEN)
    write("index_out_of_range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", BROKEN)
    write("negative_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", BROKEN)
    write("nan_vertex.off", "OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n", BROKEN)
    write("absurd_count.off", "OFF\n4000000000 1 0\n0 0 0\n", BROKEN)
    write("truncated.off", "OFF\n3 2 0\n0 0 0          \n1 0 0          \n0 1 0\n3 0 1 2\n", BROKEN)
    write("nan_vertex.stl", b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 nan\n"
          b"vertex 0 1 0\nendloop\nendfacet\nendsolid x\n", BROKEN)
    write("unclosed_facet.stl", b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", BROKEN)
    write("mesh.unknownext", "v 0 0 0\n", BROKEN)
    write("not_json.gltf", "{ this is not json", BROKEN)


if __name__ == "__main__":
    os.makedirs(BROKEN, exist_ok=True)
    ply_big_endian()
    ply_little_uchar_ushort()
    stl = stl_binary_solid_header()
    g, buf = gltf_fixture()
    glb_bytes = glb(g, buf)
    write("scene_transforms.glb", glb_bytes)
    broken(stl, glb_bytes)
