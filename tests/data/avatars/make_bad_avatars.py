#!/usr/bin/env python3
"""Writes the named bad avatars of tests/data/avatars/bad/ (spec/rigs.md, "Avatars"): small glTF
binaries each breaking one rule of fapcast's avatar reader. Run from this directory; the files are
committed, this script documents how they were made."""
import json
import struct


def glb(doc, bin_bytes=b'', *, version=2, length_delta=0, json_text=None):
    text = (json_text if json_text is not None else json.dumps(doc, separators=(',', ':'))).encode()
    text += b' ' * (-len(text) % 4)
    bin_bytes += b'\0' * (-len(bin_bytes) % 4)
    chunks = struct.pack('<I4s', len(text), b'JSON') + text
    if bin_bytes:
        chunks += struct.pack('<I4s', len(bin_bytes), b'BIN\0') + bin_bytes
    return struct.pack('<4sII', b'glTF', version, 12 + len(chunks) + length_delta) + chunks


def mesh_doc(triangles, vertices, target_names=None, targets=1, count_override=None, extra=None):
    """One mesh: `vertices` positions (float VEC3), `triangles` index triples (uint16), `targets`
    morph targets moving vertex 0 up, named `target_names` (None: no names)."""
    pos = b''.join(struct.pack('<3f', *v) for v in vertices)
    tgt = b''.join(struct.pack('<3f', 0, 0.01 if i == 0 else 0, 0) for i in range(len(vertices)))
    idx = b''.join(struct.pack('<3H', *t) for t in triangles)
    idx += b'\0' * (-len(idx) % 4)
    bin_bytes = pos + tgt + idx
    n = len(vertices)
    doc = {
        'asset': {'version': '2.0', 'generator': 'make_bad_avatars.py'},
        'scene': 0, 'scenes': [{'nodes': [0]}], 'nodes': [{'name': 'head', 'mesh': 0}],
        'meshes': [{'name': 'head', 'primitives': [{
            'attributes': {'POSITION': 0}, 'indices': 2,
            'targets': [{'POSITION': 1}] * targets}]}],
        'buffers': [{'byteLength': len(bin_bytes)}],
        'bufferViews': [
            {'buffer': 0, 'byteOffset': 0, 'byteLength': len(pos)},
            {'buffer': 0, 'byteOffset': len(pos), 'byteLength': len(tgt)},
            {'buffer': 0, 'byteOffset': len(pos) + len(tgt), 'byteLength': 6 * len(triangles)}],
        'accessors': [
            {'bufferView': 0, 'componentType': 5126, 'count': count_override or n, 'type': 'VEC3',
             'min': [min(v[k] for v in vertices) for k in range(3)], 'max': [max(v[k] for v in vertices) for k in range(3)]},
            {'bufferView': 1, 'componentType': 5126, 'count': n, 'type': 'VEC3', 'min': [0, 0, 0], 'max': [0, 0.01, 0]},
            {'bufferView': 2, 'componentType': 5123, 'count': 3 * len(triangles), 'type': 'SCALAR'}],
    }
    if target_names is not None:
        doc['meshes'][0]['extras'] = {'targetNames': target_names}
    if extra:
        extra(doc)
    return doc, bin_bytes


QUAD = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, 1)]
GOOD_TRIS = [(0, 1, 2), (0, 2, 3)]

files = {}
doc, b = mesh_doc(GOOD_TRIS, QUAD, targets=0)
del doc['meshes'][0]['primitives'][0]['targets']
files['bad.001.avatar-no-morph-targets.glb'] = glb(doc, b)
doc, b = mesh_doc(GOOD_TRIS, QUAD, target_names=None)
files['bad.002.avatar-unnamed-targets.glb'] = glb(doc, b)
doc, b = mesh_doc(GOOD_TRIS, QUAD, target_names=['Smile', 'OpenMouth'], targets=2)
files['bad.003.avatar-no-known-targets.glb'] = glb(doc, b)
# three triangles on the edge 0-2: not a surface
doc, b = mesh_doc([(0, 1, 2), (0, 2, 3), (0, 2, 4)], QUAD, target_names=['jawOpen'])
files['bad.004.avatar-non-manifold.glb'] = glb(doc, b)
# claims five million vertices
doc, b = mesh_doc(GOOD_TRIS, QUAD, target_names=['jawOpen'], count_override=5_000_000)
files['bad.005.avatar-too-large.glb'] = glb(doc, b)
doc, b = mesh_doc(GOOD_TRIS, QUAD, target_names=['jawOpen'] + [f't{i}' for i in range(1024)], targets=1025)
files['bad.006.avatar-too-large.glb'] = glb(doc, b)
doc, b = mesh_doc([(0, 1, 9)], QUAD, target_names=['jawOpen'])
files['bad.007.gltf-indices.glb'] = glb(doc, b)
doc, b = mesh_doc(GOOD_TRIS, QUAD, target_names=['jawOpen'], extra=lambda d: d.update(extensionsRequired=['EXT_meshopt_compression'], extensionsUsed=['EXT_meshopt_compression']))
files['bad.008.avatar-compressed.glb'] = glb(doc, b)
doc, b = mesh_doc(GOOD_TRIS, QUAD, target_names=['jawOpen'])
files['bad.009.glb-container.glb'] = glb(doc, b, version=1)
files['bad.010.glb-container.glb'] = glb(doc, b, length_delta=8)
files['bad.011.glb-syntax.glb'] = glb(doc, b, json_text=json.dumps(doc)[:-3])
doc, b = mesh_doc(GOOD_TRIS, QUAD, target_names=['jawOpen'], extra=lambda d: d['bufferViews'][2].update(byteLength=4))
files['bad.012.gltf-accessor.glb'] = glb(doc, b)
for name, data in files.items():
    with open('bad/' + name, 'wb') as f:
        f.write(data)
# a good minimal avatar: the same square with jawOpen and viseme_aa
doc, b = mesh_doc(GOOD_TRIS, QUAD, target_names=['jawOpen', 'viseme_aa'], targets=2)
with open('square-jawopen.glb', 'wb') as f:
    f.write(glb(doc, b))
