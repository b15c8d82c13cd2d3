#!/usr/bin/env python3
"""Builds public/data/food-embeddings.bin, the compressed food-domain word-vector table of foon-planner.

Source: the 35-dimensional GloVe vectors trained on recipe text that ship inside the PyPI package
ingredient-parser-nlp (MIT licence), file ingredient_parser/en/data/ingredient_embeddings.35d.glove.txt.gz.
Its words are Snowball (Porter2) English stems; foon-core stems queries with the same algorithm.

Usage (from the repository root):
    python3 -m venv .venv
    .venv/bin/pip install --no-deps -r scripts/requirements-embeddings.txt
    .venv/bin/python scripts/build_embeddings.py          # writes public/data/
    .venv/bin/python scripts/build_embeddings.py --check  # verifies the shipped files are reproduced

The output is a pure function of the source file (checked against a pinned SHA-256), so the table is
rebuilt bit for bit. Only the standard library is used.

Format (all integers little endian), version 1:
    magic    8 bytes  b"FOONEMB\\0"
    version  u32      1
    dims     u32      number of dimensions (35)
    count    u32      number of words
    wordlen  u32      length in bytes of the word blob
    words    wordlen  UTF-8 words, each followed by b"\\n", in the order of the source file
    scales   count x f32   per-row scale: component = int8 * scale
    vectors  count x dims x i8
    crc32    u32      CRC-32 (IEEE, as zlib.crc32) of every byte before it
"""

import argparse
import gzip
import hashlib
import importlib.metadata
import math
import pathlib
import struct
import sys
import zlib

PACKAGE = "ingredient-parser-nlp"
PACKAGE_VERSION = "2.9.1"
SOURCE_PATH = "ingredient_parser/en/data/ingredient_embeddings.35d.glove.txt.gz"
# SHA-256 of the uncompressed source text in the pinned version: a changed source stops the build.
SOURCE_TEXT_SHA256 = "2de5bf75ab10e01e3feaa5dc5509076861af108987d27ccd161ef552bbdf531f"

MAGIC = b"FOONEMB\0"
VERSION = 1
DIMS = 35

ROOT = pathlib.Path(__file__).resolve().parent.parent
OUT_DIR = ROOT / "public" / "data"
TABLE = "food-embeddings.bin"


def source_file() -> pathlib.Path:
    version = importlib.metadata.version(PACKAGE)
    if version != PACKAGE_VERSION:
        sys.exit(f"{PACKAGE} {version} is installed; this script is pinned to {PACKAGE_VERSION}")
    for f in importlib.metadata.files(PACKAGE) or []:
        if str(f).replace("\\", "/") == SOURCE_PATH:
            return pathlib.Path(f.locate())
    sys.exit(f"{SOURCE_PATH} is not in the installed {PACKAGE}")


def read_vectors(path: pathlib.Path):
    text = gzip.decompress(path.read_bytes())
    digest = hashlib.sha256(text).hexdigest()
    if digest != SOURCE_TEXT_SHA256:
        sys.exit(f"source text SHA-256 {digest} differs from the pinned {SOURCE_TEXT_SHA256}")
    words, rows = [], []
    seen = set()
    for n, line in enumerate(text.decode("utf-8").split("\n")):
        parts = line.rstrip("\r").split(" ")
        if len(parts) != DIMS + 1:
            continue  # the header line ("19850 35") and the final empty line
        word = parts[0]
        if word == "<unk>" or word in seen or not word or "\n" in word:
            continue
        seen.add(word)
        words.append(word)
        rows.append([float(x) for x in parts[1:]])
    return words, rows, digest


def quantise(row):
    """int8 components and the f32 scale with component ~= q * scale (symmetric, round half away)."""
    peak = max(abs(x) for x in row)
    if peak == 0.0:
        return 0.0, [0] * len(row)
    scale = struct.unpack("<f", struct.pack("<f", peak / 127.0))[0]
    q = []
    for x in row:
        v = abs(x) / scale
        r = int(math.floor(v + 0.5))
        r = min(r, 127)
        q.append(-r if x < 0 else r)
    return scale, q


def build(words, rows) -> bytes:
    blob = "".join(w + "\n" for w in words).encode("utf-8")
    out = bytearray()
    out += MAGIC
    out += struct.pack("<IIII", VERSION, DIMS, len(words), len(blob))
    out += blob
    scales, vectors = bytearray(), bytearray()
    for row in rows:
        scale, q = quantise(row)
        scales += struct.pack("<f", scale)
        vectors += struct.pack(f"<{DIMS}b", *q)
    out += scales
    out += vectors
    out += struct.pack("<I", zlib.crc32(bytes(out)) & 0xFFFFFFFF)
    return bytes(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="verify the shipped files instead of writing")
    args = ap.parse_args()
    words, rows, digest = read_vectors(source_file())
    table = build(words, rows)
    sha = hashlib.sha256(table).hexdigest()
    outputs = {
        TABLE: table,
        TABLE + ".sha256": f"{sha}  {TABLE}\n".encode(),
    }
    if args.check:
        bad = [n for n, b in outputs.items() if (OUT_DIR / n).read_bytes() != b]
        if bad:
            sys.exit(f"not reproduced: {', '.join(bad)}")
        print(f"ok: {TABLE} reproduced ({len(table)} bytes, sha256 {sha})")
        return
    OUT_DIR.mkdir(parents=True, exist_ok=True)
    for n, b in outputs.items():
        (OUT_DIR / n).write_bytes(b)
    gz = len(gzip.compress(table, 9, mtime=0))
    print(f"{len(words)} words x {DIMS} dims; source sha256 {digest}")
    print(f"wrote {TABLE}: {len(table)} bytes raw, {gz} bytes gzip -9; sha256 {sha}")


if __name__ == "__main__":
    main()
