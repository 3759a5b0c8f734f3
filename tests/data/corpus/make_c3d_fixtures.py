#!/usr/bin/env python3
"""Writes the C3D fixtures fapcast's own writer cannot produce: integer storage with analog
channels and events, and hostile or unsupported files. Independent of the C++ code (struct
module, from the C3D manual's layout), so the reader is tested against a second writer.
Run from tests/data/corpus: python3 make_c3d_fixtures.py"""
import struct

BLOCK = 512


def entry(name, gid, body, last=False):
    nxt = 0 if last else 2 + len(body)
    return struct.pack('<bb', len(name), gid) + name.encode() + struct.pack('<h', nxt) + body


def group(gid, name):
    return entry(name, -gid, b'\x00')


def param(gid, name, typ, dims, data, last=False):
    body = struct.pack('<bB', typ, len(dims)) + bytes(dims) + data + b'\x00'
    return entry(name, gid, body, last)


def text_rows(rows, width):
    return b''.join(r.ljust(width).encode() for r in rows)


def c3d(points, frames, labels, scale, rate, analog_used=0, analog_ratio=1, processor=84,
        storage='int', units='mm', data_start=None, header_points=None, header_analog=None,
        truncate=None, key=0x50, labels2=None, with_events=False, missing=(), used_as_text=False):
    analog = analog_used * analog_ratio
    sec = group(1, 'POINT') + group(2, 'ANALOG') + group(3, 'EVENT')
    sec += (param(1, 'USED', -1, [1], b'3') if used_as_text
            else param(1, 'USED', 2, [], struct.pack('<H', points)))
    sec += param(1, 'SCALE', 4, [], struct.pack('<f', scale))
    sec += param(1, 'RATE', 4, [], struct.pack('<f', rate))
    sec += param(1, 'DATA_START', 2, [], b'@@')  # patched once the section size is known
    sec += param(1, 'FRAMES', 2, [], struct.pack('<H', frames))
    sec += param(1, 'UNITS', -1, [len(units)], units.encode())
    w = max(len(l) for l in labels) if labels else 1
    sec += param(1, 'LABELS', -1, [w, len(labels)], text_rows(labels, w))
    if labels2:
        w2 = max(len(l) for l in labels2)
        sec += param(1, 'LABELS2', -1, [w2, len(labels2)], text_rows(labels2, w2))
    sec += param(2, 'USED', 2, [], struct.pack('<H', analog_used))
    sec += param(2, 'RATE', 4, [], struct.pack('<f', rate * analog_ratio))
    sec += param(3, 'USED', 2, [], struct.pack('<H', 1), last=True)
    nblocks = (4 + len(sec) + BLOCK - 1) // BLOCK
    ds = 2 + nblocks if data_start is None else data_start
    sec = sec.replace(b'@@', struct.pack('<H', ds))
    head = struct.pack('<BB', 2, key)
    head += struct.pack('<HHHHH', points if header_points is None else header_points,
                        analog if header_analog is None else header_analog, 1, frames, 0)
    head += struct.pack('<f', scale) + struct.pack('<HH', ds, analog_ratio) + struct.pack('<f', rate)
    head = head.ljust(2 * 147, b'\x00')
    if with_events:  # word 148-: label/range key, 4-char event labels, one event at 0.5 s
        head += struct.pack('<HHHH', 0, 0, 12345, 1) + b'\x00\x00' + struct.pack('<f', 0.5)
    head = head.ljust(BLOCK, b'\x00')
    psec = (struct.pack('<BBBB', 1, 0x50, nblocks, processor) + sec).ljust(nblocks * BLOCK, b'\x00')
    data = b''
    for f in range(frames):
        for p in range(points):
            if (f, p) in missing:
                vals = (0, 0, 0, -1)
            else:
                vals = (10 * p + f, -3 * p, 100 + f, 5)  # raw units; x scale gives mm
            data += struct.pack('<hhhh', *vals) if storage == 'int' else struct.pack('<ffff', *vals)
        for a in range(analog):
            data += struct.pack('<h', 1000 + a) if storage == 'int' else struct.pack('<f', 1000 + a)
    out = head + psec + data
    out = out.ljust((len(out) + BLOCK - 1) // BLOCK * BLOCK, b'\x00')
    return out[:truncate] if truncate is not None else out


def write(path, data):
    with open(path, 'wb') as f:
        f.write(data)


LAB = ['8.1', '8.2', 'HEAD_L']
# Good: integer storage, scale 0.5 mm, 2 analog channels at 4x the point rate, an event, a gap.
write('good/int_analog.c3d', c3d(3, 5, LAB, 0.5, 60.0, analog_used=2, analog_ratio=4,
                                 with_events=True, missing={(2, 1)}))
# Good: float storage from this independent writer, in metres.
write('good/float_metres.c3d', c3d(3, 4, LAB, -0.001, 100.0, storage='float', units='m'))
# Good: 260 markers, so labels continue in POINT:LABELS2.
many = ['M%03d' % i for i in range(260)]
write('good/labels2.c3d', c3d(260, 2, many[:255], 1.0, 60.0, labels2=many[255:]))

write('bad/bad.001.c3d-truncated.c3d', c3d(3, 5, LAB, 0.5, 60.0, truncate=300))
write('bad/bad.002.c3d-bad-key.c3d', c3d(3, 5, LAB, 0.5, 60.0, key=0x51))
write('bad/bad.003.c3d-processor-unsupported.c3d', c3d(3, 5, LAB, 0.5, 60.0, processor=85))
write('bad/bad.004.c3d-processor-unsupported.c3d', c3d(3, 5, LAB, 0.5, 60.0, processor=86))
write('bad/bad.005.c3d-bad-processor.c3d', c3d(3, 5, LAB, 0.5, 60.0, processor=7))
write('bad/bad.006.c3d-count-mismatch.c3d', c3d(3, 5, LAB, 0.5, 60.0, header_points=4))
# Claims 5 frames of 3 points and 8 analog samples; the data stops after frame 2.
write('bad/bad.007.c3d-truncated.c3d', c3d(3, 5, LAB, 0.5, 60.0, analog_used=2, analog_ratio=4,
                                           truncate=2 * BLOCK + 2 * (3 * 8 + 16)))
write('bad/bad.008.c3d-layout.c3d', c3d(3, 5, LAB, 0.5, 60.0, data_start=2))
write('bad/bad.009.c3d-bad-scale.c3d', c3d(3, 5, LAB, 0.0, 60.0))
write('bad/bad.010.c3d-units.c3d', c3d(3, 5, LAB, 0.5, 60.0, units='ft'))
write('bad/bad.011.c3d-count-mismatch.c3d', c3d(3, 5, LAB, 0.5, 60.0, analog_used=2,
                                                analog_ratio=4, header_analog=6))
write('bad/bad.012.c3d-bad-rate.c3d', c3d(3, 5, LAB, 0.5, -60.0))
# A parameter whose dimensions promise more bytes than the parameter section holds.
bad = bytearray(c3d(3, 5, LAB, 0.5, 60.0))
i = bad.find(b'LABELS')
bad[i + 10] = 255  # name, next offset (2), type, ndims, then the dims: 255 x 255 characters
bad[i + 11] = 255
write('bad/bad.013.c3d-bad-parameter.c3d', bytes(bad))
# POINT:USED stored as one character: a count must not be read as 4 bytes of float.
write('bad/bad.014.c3d-bad-parameter.c3d', c3d(3, 5, LAB, 0.5, 60.0, used_as_text=True))
