#!/usr/bin/env python3
"""Writes tests/data/corpus/bad-corpora/: one directory per rule the voice build's corpus reader
(synth/voice_corpus.hpp) refuses in TRC/CSV/.lab corpora, named bad.NNN.<rule>. Markers are
made-up numbers on the 39 sites of spec/markers.tsv (not a face): these corpora are refused
before any geometry matters. Golden messages: bad-corpora/EXPECTED.txt (regenerate with
FAPCAST_REGENERATE=1 fapcast_pipeline_tests --gtest_filter=*BadCorpora*)."""
import json, os, shutil

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "bad-corpora")
SITES = []
with open(os.path.join(HERE, "..", "..", "..", "spec", "markers.tsv")) as f:
    for line in f:
        if line.startswith("#") or not line.strip() or line.startswith("label"):
            continue
        SITES.append(line.split("\t")[0])


def csv(rate, frames, sites=SITES):
    head = "# frame_rate_hz=%g\n# units=mm\nframe,time_s" % rate
    head += "".join(",%s.x,%s.y,%s.z" % (s, s, s) for s in sites) + "\n"
    rows = ""
    for f in range(frames):
        rows += "%d,%r" % (f + 1, f / rate)
        rows += "".join(",%d,%d,%d" % (10 * i + f, -i, 100 + i) for i in range(len(sites))) + "\n"
    return head + rows


def corpus(name, files):
    d = os.path.join(OUT, name)
    os.makedirs(d)
    for file, text in files.items():
        with open(os.path.join(d, file), "w", newline="\n") as f:
            f.write(text)


LAB = "0.0 0.1 sil\n0.1 0.2 b\n"
shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
corpus("bad.001.corpus-ambiguous", {"u1.c3d": "", "u1.trc": "", "u1.lab": LAB})
corpus("bad.002.corpus-ambiguous", {"u1.csv": "", "u1.TextGrid": "", "u1.lab": LAB})
corpus("bad.003.corpus-format", {"u1.bvh": "", "u1.lab": LAB, "manifest.json": json.dumps(
    {"utterances": [{"id": "u1", "files": {"markers": "u1.bvh", "alignment": "u1.lab"}}]})})
corpus("bad.004.corpus-manifest", {"u1.csv": csv(60, 12), "u1.lab": LAB, "manifest.json": json.dumps(
    {"phone_set": "sampa", "utterances": [{"id": "u1", "files": {"markers": "u1.csv", "alignment": "u1.lab"}}]})})
corpus("bad.005.corpus-frame-rate", {"u1.csv": csv(30, 6), "u1.lab": LAB})
corpus("bad.006.corpus-frame-rate", {"u1.csv": csv(100, 20), "u1.lab": LAB, "manifest.json": json.dumps(
    {"frame_rate_hz": 120, "utterances": [{"id": "u1", "files": {"markers": "u1.csv", "alignment": "u1.lab"}}]})})
corpus("bad.007.corpus-alignment", {"u1.csv": csv(60, 12), "u1.lab": "0.0 0.1 sil\n\n0.1 0.2 xx\n"})
corpus("bad.008.corpus-alignment", {"u1.csv": csv(120, 24), "u1.lab": "0.0 0.05 pcl\n0.05 0.1 p\n0.1 0.2 h#\n",
                                    "manifest.json": json.dumps({"phone_set": "arpabet", "utterances": [
                                        {"id": "u1", "files": {"markers": "u1.csv", "alignment": "u1.lab"}}]})})
corpus("bad.009.corpus-length", {"u1.csv": csv(60, 12), "u1.lab": "0 5000000 sil\n5000000 10000000 b\n"})
corpus("bad.010.corpus-file-missing", {"u1.csv": csv(60, 12), "u2.lab": LAB})
corpus("bad.011.corpus-markers", {"u1.csv": csv(60, 12, SITES[:-1]), "u1.lab": LAB})
