# A minimal VRM 1.0 for fapcast's tests (one triangle mesh with 5 morph targets + the 15 required
# humanoid bones as empty nodes) : what @pixiv/three-vrm needs to load a VRM and play a .vrma on it (tests/cli/rig_cli_test.cpp).
import json, struct, sys
pos = [0,0,0, 1,0,0, 0,1,0]
targets = [[0,0,0, 0,0,0, 0,0.1*(k+1),0] for k in range(5)]
buf = b''.join(struct.pack('<9f', *p) for p in [pos] + targets) + struct.pack('<3I', 0, 1, 2)
bones = ['hips','spine','head','leftUpperLeg','leftLowerLeg','leftFoot','rightUpperLeg','rightLowerLeg','rightFoot',
         'leftUpperArm','leftLowerArm','leftHand','rightUpperArm','rightLowerArm','rightHand']
nodes = [{'name': 'face', 'mesh': 0}] + [{'name': b, 'translation': [0, 0.01*i, 0]} for i, b in enumerate(bones)]
# hierarchy: hips is root child of scene, everyone else child of hips (flat) — spec needs parent chains? try flat
nodes[1]['children'] = list(range(2, len(nodes)))
acc = [{'bufferView': i, 'componentType': 5126, 'count': 3, 'type': 'VEC3',
        'min': [0,0,0], 'max': [1,1,0] if i == 0 else [0, 0.1*i, 0]} for i in range(6)]
acc.append({'bufferView': 6, 'componentType': 5125, 'count': 3, 'type': 'SCALAR'})
bvs = [{'buffer': 0, 'byteOffset': 36*i, 'byteLength': 36} for i in range(6)] + [{'buffer': 0, 'byteOffset': 216, 'byteLength': 12}]
names = ['aa','ih','ou','ee','oh']
gltf = {'asset': {'version': '2.0', 'generator': 'tests/data/avatars/make_vrm_fixture.py'},
  'extensionsUsed': ['VRMC_vrm'], 'scene': 0, 'scenes': [{'nodes': [0, 1]}], 'nodes': nodes,
  'meshes': [{'name': 'face', 'primitives': [{'attributes': {'POSITION': 0}, 'indices': 6, 'targets': [{'POSITION': k+1} for k in range(5)]}],
              'weights': [0]*5, 'extras': {'targetNames': names}}],
  'accessors': acc, 'bufferViews': bvs, 'buffers': [{'byteLength': len(buf)}],
  'extensions': {'VRMC_vrm': {'specVersion': '1.0',
     'meta': {'name': 'probe', 'version': '1', 'authors': ['fapcast'], 'licenseUrl': 'https://vrm.dev/licenses/1.0/',
              'avatarPermission': 'everyone', 'commercialUsage': 'corporation', 'allowRedistribution': True, 'modification': 'allowModificationRedistribution'},
     'humanoid': {'humanBones': {b: {'node': i + 1} for i, b in enumerate(bones)}},
     'expressions': {'preset': {n: {'morphTargetBinds': [{'node': 0, 'index': k, 'weight': 1.0}]} for k, n in enumerate(names)}}}}}
js = json.dumps(gltf, separators=(',', ':')).encode()
js += b' ' * (-len(js) % 4); buf += b'\0' * (-len(buf) % 4)
out = struct.pack('<4sII', b'glTF', 2, 12 + 8 + len(js) + 8 + len(buf)) + struct.pack('<I4s', len(js), b'JSON') + js + struct.pack('<I4s', len(buf), b'BIN\0') + buf
open(sys.argv[1] if len(sys.argv) > 1 else "five-vowels.vrm", "wb").write(out)
