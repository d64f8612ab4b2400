#!/usr/bin/env python3
"""Writes the mesh fuzz seeds, tests/fuzz/corpus/mesh_file/ and corpus/mesh_scene/: a tiny
valid mesh per format assimp reads for us (byte 0 of each seed picks the extension, as
mesh_fuzz_inputs.hpp says) and a few scene records in the layout of
core/mesh/imported_scene.cpp. Run again only to change the seeds; the result is committed."""
import base64, json, os, struct, sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
EXT = [".obj", ".stl", ".ply", ".off", ".ac", ".gltf", ".glb", ".dae", ".3ds", ".fbx"]

def seed(name, ext, body):
    d = os.path.join(ROOT, "mesh_file")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(bytes([EXT.index(ext)]) + (body.encode() if isinstance(body, str) else body))

QUAD = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
seed("quad.obj", ".obj", "o quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nusemtl red\nf 1//1 2//1 3//1 4//1\n")
seed("tri.stl", ".stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
     "endloop\nendfacet\nendsolid t\n")
stl = b"\0" * 80 + struct.pack("<I", 1) + struct.pack("<12fH", 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0)
seed("tri_binary.stl", ".stl", stl)
seed("quad.ply", ".ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
     "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
     + "".join("%d %d %d\n" % v for v in QUAD) + "4 0 1 2 3\n")
seed("quad.off", ".off", "OFF\n4 1 0\n" + "".join("%d %d %d\n" % v for v in QUAD) + "4 0 1 2 3\n")
seed("tri.ac", ".ac", 'AC3Db\nMATERIAL "red" rgb 1 0 0  amb 0.2 0.2 0.2  emis 0 0 0  spec 0.5 0.5 0.5  shi 10  trans 0\n'
     'OBJECT world\nkids 1\nOBJECT poly\nname "t"\nloc 0 0 1\nnumvert 3\n0 0 0\n1 0 0\n0 1 0\nnumsurf 1\n'
     'SURF 0x10\nmat 0\nrefs 3\n0 0 0\n1 0 0\n2 0 0\nkids 0\n')
pos = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
idx = struct.pack("<3H", 0, 1, 2) + b"\0\0"
buf = pos + idx
def gltf(uri):
    g = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
         "nodes": [{"mesh": 0, "translation": [0, 0, 2]}],
         "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
         "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1]}}],
         "buffers": [dict({"byteLength": len(buf)}, **({"uri": uri} if uri else {}))],
         "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                         {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
         "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                        "min": [0, 0, 0], "max": [1, 1, 0]},
                       {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]}
    return json.dumps(g, separators=(",", ":"))
seed("tri.gltf", ".gltf", gltf("data:application/octet-stream;base64," + base64.b64encode(buf).decode()))
j = gltf(None).encode()
j += b" " * (-len(j) % 4)
glb = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(j) + 8 + len(buf)) + struct.pack("<II", len(j), 0x4E4F534A) + j \
      + struct.pack("<II", len(buf), 0x004E4942) + buf
seed("tri.glb", ".glb", glb)
seed("tri.dae", ".dae", '<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" '
     'version="1.4.1"><asset><unit meter="1"/><up_axis>Z_UP</up_axis></asset><library_geometries>'
     '<geometry id="g"><mesh><source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>'
     '<technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>'
     '<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>'
     '<vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count="1">'
     '<input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry>'
     '</library_geometries><library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry '
     'url="#g"/></node></visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/>'
     '</scene></COLLADA>')

# Scene records (imported_scene.cpp): magic, up axis and sign, nodes, meshes, materials.
def u64(n): return struct.pack("<Q", n)
def node(mat, meshes, children):
    return struct.pack("<16d", *mat) + u64(len(meshes)) + struct.pack("<%dI" % len(meshes), *meshes) \
        + u64(len(children)) + struct.pack("<%dI" % len(children), *children)
def mesh(verts, normals, tris, material):
    return u64(len(verts)) + b"".join(struct.pack("<3f", *v) for v in verts) \
        + u64(len(normals)) + b"".join(struct.pack("<3f", *v) for v in normals) \
        + u64(len(tris)) + struct.pack("<%dI" % len(tris), *tris) + struct.pack("<I", material)
def material(name, rgba, tex):
    return u64(len(name)) + name.encode() + struct.pack("<4f", *rgba) + u64(len(tex)) + tex.encode()
I = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
T = I[:12] + [5, 0, 0, 1]
def record(name, up, nodes, meshes, materials):
    d = os.path.join(ROOT, "mesh_scene")
    os.makedirs(d, exist_ok=True)
    body = struct.pack("<Iii", 0x54534d31, up, 1) + u64(len(nodes)) + b"".join(nodes) \
        + u64(len(meshes)) + b"".join(meshes) + u64(len(materials)) + b"".join(materials)
    with open(os.path.join(d, name), "wb") as f:
        f.write(body)
record("one_triangle", -1, [node(I, [0], [])], [mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [], [0, 1, 2], 0)], [])
record("two_nodes_normals", 2, [node(I, [], [1]), node(T, [0, 0], [])],
       [mesh(QUAD, [(0, 0, 1)] * 4, [0, 1, 2, 0, 2, 3], 1)],
       [material("a", (1, 1, 1, 1), ""), material("b", (0.2, 0.3, 0.4, 1), "t.png")])
print("seeds written to", ROOT)
