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

Vocabulary: the source's KEEP_MOST_FREQUENT most frequent words (it lists them by falling frequency), and
every other word that is the stem of a word of a name the project knows (wasm/core/data/: food taxonomy,
aliases, dish classes, utensils, states; the starter knowledge base's labels). The rest of the source's
19,850 words are rare: misspellings, brand names, words of recipe prose; a query word among them is an
unknown word, as a word missing from the source always was. The words kept keep the source's order.

Each row is stored as the int8 components of its direction only (symmetric rounding to STEPS = 63 steps of
the row's largest component): the planner uses unit rows, so a row's length carries no information. 63
steps (7 bits) make the table 26 kB smaller in gzip than 127 and the substitution dev set's figures
(wasm/core/tests/similarity_eval.rs) no worse: top-1 88.6 % (88.0 % at 127), top-5 97.1 %; 31 steps
(6 bits) lost a name.

The output is a pure function of the source file (checked against a pinned SHA-256) and of the project's
name files, so the table is rebuilt bit for bit. Needs snowballstemmer (the Snowball English stemmer the
source's words, and foon-core's lookups, are made with), pinned in requirements-embeddings.txt.

Format (all integers little endian), version 2:
    magic    8 bytes  b"FOONEMB\\0"
    version  u32      2
    dims     u32      number of dimensions (35)
    count    u32      number of words
    wordlen  u32      length in bytes of the word blob
    words    wordlen  UTF-8 words, each followed by b"\\n", in the order of the source file
    vectors  count x dims x i8
    crc32    u32      CRC-32 (IEEE, as zlib.crc32) of every byte before it
"""

import argparse
import gzip
import hashlib
import importlib.metadata
import math
import pathlib
import re
import struct
import sys
import unicodedata
import zlib

import snowballstemmer

PACKAGE = "ingredient-parser-nlp"
PACKAGE_VERSION = "2.9.1"
SOURCE_PATH = "ingredient_parser/en/data/ingredient_embeddings.35d.glove.txt.gz"
# SHA-256 of the uncompressed source text in the pinned version: a changed source stops the build.
SOURCE_TEXT_SHA256 = "2de5bf75ab10e01e3feaa5dc5509076861af108987d27ccd161ef552bbdf531f"

MAGIC = b"FOONEMB\0"
VERSION = 2
DIMS = 35
# Rounding steps of a row's largest component (see the format above).
STEPS = 63
# The most frequent words kept whatever they are: at this rank the source's words are mostly rare
# spellings and recipe prose (the dev queries' words all rank within it).
KEEP_MOST_FREQUENT = 6000

ROOT = pathlib.Path(__file__).resolve().parent.parent
# Files of names the planner knows: every word of them keeps its vector.
NAME_FILES = sorted((ROOT / "wasm" / "core" / "data").glob("*.t*")) + sorted((ROOT / "public" / "kb" / "starter").glob("*.txt"))
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


def name_words():
    """Lower-cased, accent-folded words of the project's name files (comment lines left out), with their stems."""
    stemmer = snowballstemmer.stemmer("english")
    found = set()
    for path in NAME_FILES:
        for line in path.read_text(encoding="utf-8").split("\n"):
            if line.startswith("#") or line.startswith("//"):
                continue
            folded = unicodedata.normalize("NFKD", line.lower()).encode("ascii", "ignore").decode()
            for word in re.split(r"[^a-z0-9]+", folded):
                if word:
                    found.update((word, stemmer.stemWord(word)))
    return found


def kept(words, rows):
    """The words (and rows) of the table: the most frequent ones and those of the project's names."""
    names = name_words()
    keep = [i for i, w in enumerate(words) if i < KEEP_MOST_FREQUENT or w in names]
    return [words[i] for i in keep], [rows[i] for i in keep]


def quantise(row):
    """int8 components of the row's direction: its largest component is STEPS (symmetric, round half away)."""
    peak = max(abs(x) for x in row)
    if peak == 0.0:
        return [0] * len(row)
    # the scale as a float32, as version 1 computed it
    scale = struct.unpack("<f", struct.pack("<f", peak / STEPS))[0]
    q = []
    for x in row:
        v = abs(x) / scale
        r = int(math.floor(v + 0.5))
        r = min(r, STEPS)
        q.append(-r if x < 0 else r)
    return q


def build(words, rows) -> bytes:
    blob = "".join(w + "\n" for w in words).encode("utf-8")
    out = bytearray()
    out += MAGIC
    out += struct.pack("<IIII", VERSION, DIMS, len(words), len(blob))
    out += blob
    for row in rows:
        out += struct.pack(f"<{DIMS}b", *quantise(row))
    out += struct.pack("<I", zlib.crc32(bytes(out)) & 0xFFFFFFFF)
    return bytes(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="verify the shipped files instead of writing")
    args = ap.parse_args()
    source_words, source_rows, digest = read_vectors(source_file())
    words, rows = kept(source_words, source_rows)
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
    print(f"{len(words)} of the source's {len(source_words)} words x {DIMS} dims; source sha256 {digest}")
    print(f"wrote {TABLE}: {len(table)} bytes raw, {gz} bytes gzip -9; sha256 {sha}")


if __name__ == "__main__":
    main()
