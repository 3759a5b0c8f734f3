#!/usr/bin/env python3
"""Writes tests/data/alignment/bad/: small alignment files that each break one rule of the
readers (spec/corpus.md), named bad.NNN.<rule>.<ext>, and options.tsv: how the test reads each
(sample rate, recording length, tier; "-" for none). Written for fapcast; the shapes follow the
real files in tests/data/alignment/ (Praat, EMU, Festival, TIMIT, HTK, BAS, Gentle)."""
import os, struct, sys

out = sys.argv[1] if len(sys.argv) > 1 else 'tests/data/alignment/bad'
os.makedirs(out, exist_ok=True)
for f in os.listdir(out):
    if f.startswith('bad.') or f == 'options.tsv':
        os.remove(os.path.join(out, f))
rows = []
n = 0

def bad(rule, ext, data, rate='16000', audio='-', tier='-'):
    global n
    n += 1
    name = 'bad.%03d.%s.%s' % (n, rule, ext)
    with open(os.path.join(out, name), 'wb') as f:
        f.write(data if isinstance(data, bytes) else data.encode('utf-8'))
    rows.append((name, rate, audio, tier))

def tg_long(tiers, xmax=1.0):
    s = 'File type = "ooTextFile"\nObject class = "TextGrid"\n\nxmin = 0\nxmax = %g\ntiers? <exists>\nsize = %d\nitem []:\n' % (xmax, len(tiers))
    for k, (name, ivs) in enumerate(tiers, 1):
        s += '    item [%d]:\n        class = "IntervalTier"\n        name = "%s"\n        xmin = 0\n        xmax = %g\n        intervals: size = %d\n' % (k, name, xmax, len(ivs))
        for i, (a, b, t) in enumerate(ivs, 1):
            s += '        intervals [%d]:\n            xmin = %g\n            xmax = %g\n            text = "%s"\n' % (i, a, b, t)
    return s

def w16(s):
    if all(ord(c) < 128 for c in s):
        return struct.pack('>H', len(s)) + s.encode('ascii')
    u = s.encode('utf-16-be')
    return struct.pack('>HH', 0xFFFF, len(s)) + u

def tg_binary(tiers, xmax=1.0, klass=b'TextGrid', flag=1, extra=b''):
    b = b'ooBinaryFile' + bytes([len(klass)]) + klass + struct.pack('>dd', 0.0, xmax) + bytes([flag])
    b += struct.pack('>i', len(tiers))
    for name, ivs in tiers:
        b += bytes([12]) + b'IntervalTier' + w16(name) + struct.pack('>dd', 0.0, xmax) + struct.pack('>i', len(ivs))
        for a, e, t in ivs:
            b += struct.pack('>dd', a, e) + (t if isinstance(t, bytes) else w16(t))
    return b + extra

phones = [(0, 0.2, ''), (0.2, 0.4, 'HH'), (0.4, 0.6, 'AH0'), (0.6, 0.8, 'L'), (0.8, 1.0, 'OW1')]

# ---- Praat binary TextGrid
good_bin = tg_binary([('phones', phones)])
bad('textgrid-truncated', 'TextGrid', good_bin[:-7])
bad('textgrid-header', 'TextGrid', tg_binary([('phones', phones)], klass=b'PitchTier'))
bad('textgrid-header', 'TextGrid', b'ooBinary2File' + good_bin[len(b'ooBinaryFile'):])
bad('textgrid-syntax', 'TextGrid', tg_binary([('phones', phones)], flag=7))
bad('textgrid-encoding', 'TextGrid', tg_binary([('phones', [(0, 1, struct.pack('>HHHH', 0xFFFF, 1, 0xD800, 0x0041))])]))
bad('textgrid-interval-order', 'TextGrid', tg_binary([('phones', [(0, 0.6, 'HH'), (0.5, 1.0, 'AH0')])]))
bad('textgrid-trailing-data', 'TextGrid', good_bin + b'\x00\x00')
bad('textgrid-bad-count', 'TextGrid', good_bin[:good_bin.index(b'IntervalTier') - 5] + struct.pack('>i', -1))
# ---- Praat chronological TextGrid
chrono = '"Praat chronological TextGrid text file"\n0 1   ! Time domain.\n1   ! Number of tiers.\n"IntervalTier" "phones" 0 1\n'
bad('textgrid-syntax', 'TextGrid', chrono + '\n! phones:\n2 0 0.5\n"HH"\n')
bad('textgrid-interval-order', 'TextGrid', chrono + '\n1 0 0.6\n"HH"\n\n1 0.5 1\n"AH0"\n')
bad('textgrid-truncated', 'TextGrid', chrono + '\n1 0 0.6\n')
bad('textgrid-syntax', 'TextGrid', tg_long([('phones', [(0, 1, 'AH0"x')])]).replace('"AH0"x"', '"AH0"x'))
# ---- ESPS / xlabel / Festival
bad('esps-header', 'lab', 'signal x\nnfields 1\n0.1 125 a\n0.2 125 b\n')
bad('esps-bad-time', 'lab', 'signal x\nnfields 1\n#\n0.1 125 h#\n0,2 125 b\n')
bad('esps-fields', 'lab', '#\n0.1 h#\n')
bad('esps-time-order', 'lab', '#\n0.30 125 pau\n0.20 125 dh\n')
bad('esps-header', 'lab', 'separator ;;\nnfields 1\n#\n0.1 125 a\n')
bad('esps-encoding', 'lab', b'#\n0.1 125 \xff\n')
# ---- TIMIT
bad('timit-fields', 'phn', '0 2400\n')
bad('timit-bad-sample', 'phn', '0 2400.5 h#\n')
bad('timit-order', 'phn', '0 2400 h#\n2000 4000 sh\n')
bad('timit-needs-rate', 'phn', '0 2400 h#\n2400 4000 sh\n', rate='-')
bad('alignment-words-only', 'wrd', '2400 5000 she\n')
bad('lab-units-mismatch', 'phn', '0 2400000 h#\n2400000 4000000 sh\n4000000 31000000 iy\n', audio='3.1')
# ---- HTK .lab: sample offsets under a .lab name, HTS labels
timit_rows = '0 7812 h#\n7812 9507 sh\n9507 10610 iy\n10610 11697 hv\n11697 13744 ae\n13744 14960 dcl\n14960 15385 d\n'
bad('lab-units-mismatch', 'lab', timit_rows, audio='0.97')
bad('lab-units-mismatch', 'lab', timit_rows, rate='-')
bad('lab-state-level', 'lab', '0 50000 x^x-sil+hh=iy@x_x/A:0[2]\n50000 100000 x^x-sil+hh=iy@x_x/A:0[3]\n')
bad('lab-hts-labels', 'lab', '0 500000 x^x-sil+hh=iy@x_x/A:0\n500000 1000000 hh\n')
# ---- HTK master label files
bad('mlf-header', 'mlf', '"*/a.lab"\n0 100000 sil\n.\n')
bad('mlf-syntax', 'mlf', '#!MLF!#\n*/a.lab\n0 100000 sil\n.\n')
bad('mlf-syntax', 'mlf', '#!MLF!#\n"*/a.lab"\n0 100000 sil\n100000 5000000 ah\n')
bad('mlf-redirect', 'mlf', '#!MLF!#\n"*/a.lab" -> "labels/mono"\n')
bad('mlf-untimed', 'mlf', '#!MLF!#\n"*/a.lab"\nsil\nah\n.\n')
bad('lab-alternatives', 'mlf', '#!MLF!#\n"*/a.lab"\n0 100000 sil\n///\n0 100000 sp\n.\n')
bad('lab-interval-order', 'mlf', '#!MLF!#\n"*/a.lab"\n0 3000000 sil\n.\n"*/b.lab"\n3000000 1000000 sil\n.\n')
bad('mlf-no-entry', 'mlf', '#!MLF!#\n"*/a.lab"\n0 3000000 sil\n3000000 9000000 ah\n.\n"*/b.lab"\n0 3000000 sil\n3000000 9000000 ah\n.\n')
# ---- BAS Partitur
par_head = 'LHD: Partitur 1.3\nSAM: 16000\nLBD:\nORT:\t0\twer\nKAN:\t0\tve:6\n'
bad('partitur-syntax', 'par', par_head + 'MAU 0 7999 0 v\n')
bad('partitur-header', 'par', 'LHD: Partitur 1.3\nLBD:\nORT:\t0\twer\nMAU:\t0\t7999\t0\tv\n')
bad('partitur-header', 'par', 'LHD: Partitur 1.3\nSAM: 0\nLBD:\n')
bad('partitur-link', 'par', par_head + 'MAU:\t0\t7999\t3\tv\n')
bad('partitur-order', 'par', par_head + 'MAU:\t8000\t7999\t0\tv\nMAU:\t4000\t1999\t0\te:\n')
bad('partitur-syntax', 'par', par_head + 'MAU:\t0\tabc\t0\tv\n')
# ---- Gentle JSON
bad('gentle-json', 'json', '{"transcript": "hi", "words": [\n')
bad('gentle-json', 'json', '{"words": ' + '[' * 40 + ']' * 40 + '}')
bad('gentle-schema', 'json', '{"transcript": "hi"}')
bad('gentle-schema', 'json', '{"words": [{"case": "success", "start": 0.5, "end": 0.8, "word": "hi", "phones": [{"phone": "hh_B"}]}]}')
bad('gentle-order', 'json', '{"words": [{"case": "success", "start": 0.5, "end": 0.8, "word": "hi", "phones": [{"phone": "hh_B", "duration": 0.1}, {"phone": "ay_E", "duration": 0.2}]},'
    ' {"case": "success", "start": 0.6, "end": 0.9, "word": "yo", "phones": [{"phone": "y_B", "duration": 0.1}, {"phone": "ow_E", "duration": 0.2}]}]}')
bad('gentle-order', 'json', '{"words": [{"case": "success", "start": 0.5, "end": 1.8, "word": "hi", "phones": [{"phone": "hh_B", "duration": 0.1}, {"phone": "ay_E", "duration": 0.2}]}]}')
# ---- the choice after reading: format, tier, labels, coverage
bad('alignment-format-mismatch', 'lab', tg_long([('phones', phones)]))
bad('alignment-format-mismatch', 'TextGrid', '#\n0.1 125 h#\n0.2 125 a\n')
bad('alignment-tier-ambiguous', 'TextGrid', tg_long([('A - phones', phones), ('B - phones', phones)]))
bad('alignment-no-such-tier', 'TextGrid', tg_long([('phones', phones)]), tier='Phonetic')
bad('alignment-no-phone-tier', 'TextGrid', tg_long([('words', [(0, 1, 'hello')]), ('notes', [(0, 1, 'ok')])]))
bad('alignment-unknown-label', 'TextGrid', tg_long([('phones', [(0, 0.5, 'HH'), (0.5, 1, 'PT')])]))
bad('alignment-no-phones', 'TextGrid', tg_long([('Utterance', [(0, 0.2, ''), (0.2, 0.9, ''), (0.9, 1.0, '')]), ('Phonetic', phones)]), tier='Utterance')
bad('alignment-low-coverage', 'TextGrid', tg_long([('phones', [(0, 0.02, 'AH0'), (0.02, 1.0, 'sil')])], xmax=1.0), audio='1.0')
bad('alignment-empty', 'lab', '\n\n')

with open(os.path.join(out, 'options.tsv'), 'w') as f:
    f.write('# file\tsample_rate_hz\taudio_seconds\ttier   (how bad_alignments_test reads each; - = not given)\n')
    for r in rows:
        f.write('\t'.join(r) + '\n')
print('%d bad inputs in %s' % (n, out))
