#!/usr/bin/env python3
"""Differential check of two builds of the proof checker (proofs/checker/): runs OLD and NEW on
every shipped manifest and certificate file, and on a corpus of seeded mutations of the small
shipped certificates (byte flips, line deletions / duplications / swaps, number changes, several
certificates in one file) and of a copied manifest set; reports any input on which their
verdicts (exit code, VERIFIED or not) or their outputs differ.

    bench/compare_checkers.py OLD_CHECKER NEW_CHECKER [MUTANTS] [SEED] [OLD_CERTIFICATES]

OLD_CERTIFICATES (default: proofs/certificates) is the shipped set in OLD's format, e.g.
`git archive main proofs/certificates | tar -x -C DIR` before a format change. If OLD reads
certificate format 1 and NEW format 2 (proofs/README.md, "Format"), every input is translated:
format-1 mutants to format 2 for NEW and format-2 mutants (as many again) to format 1 for OLD,
each translation following its reader line by line (a row count decides which lines are rows,
as in the format-1 reader). Verdict differences a translation cannot avoid are counted apart,
by cause: a format-1 mutant whose `interior` section was altered (format 2 has none: the checker
computes the set), and a format-2 mutant whose rows are not in v*, f*, c* order (format 1 groups
them into sections). So are inputs OLD verifies and NEW rejects only because a claim is not
followed by exactly the computed tokens (NEW's stricter claims, e.g. `claim valences x`).

Exit 0 iff every other verdict agrees. A one-off tool for changes to the checker, not a CTest test.
"""
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHIPPED = os.path.join(ROOT, "proofs", "certificates")


def certificates(path):
    """The certificates of a file, each as its text (from 'dualhex-certificate' to 'end')."""
    out, cur = [], None
    for line in open(path, encoding="utf-8"):
        if line.startswith("dualhex-certificate"):
            cur = [line]
        elif cur is not None:
            cur.append(line)
            if line.strip() == "end":
                out.append("".join(cur))
                cur = None
    return out


def first_file(directory):
    """The first file its manifest lists (range files are named by what they hold)."""
    return re.search(r"^file (\S+)", open(os.path.join(directory, "manifest")).read(), re.M).group(1)


def smallest(path, n):
    return sorted(certificates(path), key=len)[:n]


NUMBER = re.compile(r"-?\d+")


def mutate(text, rng):
    lines = text.split("\n")
    kind = rng.randrange(7)
    if kind == 0:  # byte flip
        b = bytearray(text, "utf-8")
        i = rng.randrange(len(b))
        b[i] = ord(rng.choice("0123456789 -+\n#:abcdeflnrstux\t"))
        return "byte flip", b.decode("utf-8", "replace")
    i = rng.randrange(len(lines))
    if kind == 1:
        del lines[i]
        return "line deleted", "\n".join(lines)
    if kind == 2:
        lines.insert(i, lines[i])
        return "line duplicated", "\n".join(lines)
    if kind == 3:
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
        return "lines swapped", "\n".join(lines)
    # a number changed: +-1, +-random, negated, zero, huge, 2^19 (+1)
    spots = [(k, m) for k, line in enumerate(lines) for m in NUMBER.finditer(line)]
    if not spots:
        return "no number", text
    k, m = rng.choice(spots)
    v = int(m.group())
    new = rng.choice([v + 1, v - 1, v + rng.randrange(2, 50), -v, 0, 2**19, 2**19 + 1, -(2**19) - 1,
                      2**63, 2**64 + 5, v * 2, rng.randrange(0, 100)])
    lines[k] = lines[k][:m.start()] + str(new) + lines[k][m.end():]
    return "number changed", "\n".join(lines)


# OLD's reasons about format 1's interior list (absent from format 2), not about the complex
INTERIOR = ["declared interior", "section 'interior'", "interior vertex ", "'interior COUNT'",
            "interior: more ids"]


def tokens(line):
    return line.split("#", 1)[0].split()


def is_int(t):
    return re.fullmatch(r"-?\d+", t) is not None


def version(text):
    """The certificate format of a file: the number on its first 'dualhex-certificate' line."""
    m = re.search(r"^dualhex-certificate (\d+)", text, re.M)
    return int(m.group(1)) if m else 1


def v1_to_v2(text):
    """A format-1 text as format 2, read as the format-1 reader reads it: `vertices|faces|cells
    N` makes the next N lines rows (v / f / c), `interior all | K` and the lines holding its K
    ids are dropped; a header the format-1 reader would reject stays as it is (rejected by the
    format-2 reader too). Returns the text and whether an interior section was malformed."""
    lines = [t for t in (tokens(l) for l in text.split("\n")) if t]
    out, rows, prefix, interior_bad, seen, i = [], 0, "", False, set(), 0
    while i < len(lines):
        t = lines[i]
        i += 1
        if rows:
            out.append(prefix + " " + " ".join(t))
            rows -= 1
            continue
        key = t[0]
        if key == "dualhex-certificate":
            seen = set()
            out.append(" ".join([key] + [{"1": "2", "2": "1"}.get(x, x) for x in t[1:]]))
            continue
        order = {"vertices": None, "faces": "vertices", "cells": "faces"}
        if key in order and len(t) == 2 and is_int(t[1]) and 0 <= int(t[1]) <= len(lines) - i \
                and key not in seen and (order[key] is None or order[key] in seen):
            seen.add(key)
            rows, prefix = int(t[1]), {"vertices": "v", "faces": "f", "cells": "c"}[key]
            continue
        if key == "interior" and "interior" not in seen and len(t) == 2 and \
                (t[1] == "all" or (is_int(t[1]) and int(t[1]) >= 0)):
            seen.add(key)
            ids = 0
            while t[1] != "all" and ids < int(t[1]) and i < len(lines):
                ids += len(lines[i])
                i += 1
            interior_bad = interior_bad or (t[1] != "all" and ids != int(t[1]))
            continue
        if key == "interior":
            interior_bad = True
        out.append(" ".join(t))
    return "\n".join(out) + "\n", interior_bad


def v2_to_v1(text):
    """A format-2 text as format 1: each run of v / f / c rows becomes a counted section, and
    before each `end` the interior section the writer would give (the vertices on no face of
    one cell, computed from the rows that parse). Returns the text and whether the rows were
    out of v*, f*, c* order (then format 1 sees a section twice where format 2 does not)."""
    out, run, kinds, disordered, faces, uses = [], [], [], False, [], {}
    nv = 0

    def flush():
        if run:
            out.append("%s %d" % ({"v": "vertices", "f": "faces", "c": "cells"}[run[0][0]], len(run)))
            out.extend(" ".join(t[1:]) for t in run)
            run.clear()

    for t in (tokens(l) for l in text.split("\n")):
        if not t:
            continue
        key = t[0]
        if key in ("v", "f", "c"):
            if run and run[0][0] != key:
                flush()
            if not run:
                kinds.append(key)
            run.append(t)
            nv += key == "v"
            if key == "f":
                faces.append([int(x) for x in t[1:] if is_int(x)])
            if key == "c":
                for x in t[1:]:
                    if x[:1] in "+-" and x[1:].isdigit():
                        uses[int(x[1:])] = uses.get(int(x[1:]), 0) + 1
            continue
        flush()
        if key == "end":
            boundary = {v for f, vs in enumerate(faces) if uses.get(f) == 1 for v in vs}
            inner = [str(v) for v in range(nv) if v not in boundary]
            out.extend(["interior %d" % len(inner)] + ([" ".join(inner)] if inner else []))
        if key in ("end", "dualhex-certificate"):
            disordered = disordered or kinds not in ([], ["v"], ["v", "f"], ["v", "f", "c"])
            kinds, faces, uses, nv = [], [], {}, 0
        if key == "dualhex-certificate":
            t = [key] + [{"1": "2", "2": "1"}.get(x, x) for x in t[1:]]
        out.append(" ".join(t))
    flush()
    return "\n".join(out) + "\n", disordered


def run(checker, args):
    p = subprocess.run([checker] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
    out = p.stdout.decode("utf-8", "replace")
    return p.returncode, "VERIFIED" in out, out


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    old, new = sys.argv[1], sys.argv[2]
    mutants = int(sys.argv[3]) if len(sys.argv) > 3 else 3000
    rng = random.Random(int(sys.argv[4]) if len(sys.argv) > 4 else 14)
    old_shipped = sys.argv[5] if len(sys.argv) > 5 else SHIPPED
    translate = version(open(os.path.join(old_shipped, "elements.cert")).read()) != \
        version(open(os.path.join(SHIPPED, "elements.cert")).read())
    tmp = tempfile.mkdtemp(prefix="dualhex-compare-")
    tally = {"inputs": 0, "verified": 0, "rejected": 0, "verdict differs": 0, "output differs": 0,
             "interior section altered (apart)": 0, "rows out of order (apart)": 0,
             "claim not written as computed (apart: stricter)": 0}
    shown = 0

    def rejections(out):
        return [l for l in out.split("\n") if l.startswith("REJECTED")]

    def compare(old_args, new_args, what, apart=None):
        nonlocal shown
        a, b = run(old, old_args), run(new, new_args)
        tally["inputs"] += 1
        tally["verified" if b[1] else "rejected"] += 1
        reasons = rejections(b[2])
        if a[1] and reasons and all("a claim is not the computed" in l for l in reasons):
            apart = "claim not written as computed (apart: stricter)"  # e.g. 'claim valences x'
        if translate and any(r in l for l in rejections(a[2]) for r in INTERIOR):
            apart = "interior section altered (apart)"  # OLD's only objection: format 1's list
        if a[:2] != b[:2] and apart:
            tally[apart] += 1
            print("verdict differs, %s:" % apart, what, "old", a[:2], "new", b[:2])
        elif a[:2] != b[:2]:
            tally["verdict differs"] += 1
            keep = tempfile.mkdtemp(prefix="dualhex-compare-differs-")
            for f in old_args[-1:] + new_args[-1:]:
                shutil.copy(f, os.path.join(keep, ("old-" if f in old_args else "new-") + os.path.basename(f)))
            print("VERDICT DIFFERS:", what, "old", a[:2], "new", b[:2], "inputs kept in", keep)
        elif a[2].replace(old, "CHECKER").replace(old_shipped, "SHIPPED").replace(tmp + "/old-", tmp + "/") \
                .replace("old.cert", "new.cert") != b[2].replace(new, "CHECKER").replace(SHIPPED, "SHIPPED"):
            tally["output differs"] += 1
            if shown < 10:
                shown += 1
                diff = [(x, y) for x, y in zip(a[2].split("\n"), b[2].split("\n")) if x != y][:2]
                print("output differs:", what, diff)

    # (a) every shipped manifest and every shipped certificate file
    for d in ["", "weak", "variants", "windows", "boundary", "weak_spread"]:
        if not os.path.isdir(os.path.join(old_shipped, d)):
            continue
        compare([os.path.join(old_shipped, d, "manifest")], [os.path.join(SHIPPED, d, "manifest")],
                "shipped manifest " + d)
        for f in sorted(os.listdir(os.path.join(SHIPPED, d))):  # those of the same name in both
            if f.endswith(".cert") and os.path.exists(os.path.join(old_shipped, d, f)):
                compare(["--file", os.path.join(old_shipped, d, f)], ["--file", os.path.join(SHIPPED, d, f)],
                        "shipped file " + d + "/" + f)
    shipped = tally["inputs"]

    # (b) mutations of the small certificates: the 13 elements, the 4 smallest variant elements,
    # the mask-0 torus, the 2 smallest windows and the smallest weak torus; with a format change
    # first in OLD's format (translated for NEW), then as many in NEW's (translated for OLD)
    def seeds(root):
        return (certificates(os.path.join(root, "elements.cert")) +
                smallest(os.path.join(root, "variants", "elements.cert"), 4) +
                certificates(os.path.join(root, "configurations-000-021.cert"))[:1] +
                smallest(os.path.join(root, "windows", "windows-0000-0099.cert"), 2) +
                smallest(os.path.join(root, "weak", first_file(os.path.join(root, "weak"))), 1))
    kinds = {}
    old_path, new_path = os.path.join(tmp, "old.cert"), os.path.join(tmp, "new.cert")
    rounds = [(old_shipped, "format of OLD")] + ([(SHIPPED, "format of NEW")] if translate else [])
    for root, fmt in rounds:
        pool = seeds(root)
        for n in range(mutants):
            text = rng.choice(pool)
            what = []
            for _ in range(rng.choice([1, 1, 1, 2, 3])):
                w, text = mutate(text, rng)
                what.append(w)
            if rng.randrange(8) == 0:  # several certificates in one file: resynchronisation
                text = text + rng.choice(pool) + (mutate(rng.choice(pool), rng)[1] if rng.randrange(2) else "")
                what.append("+ more certificates")
            kinds[what[0]] = kinds.get(what[0], 0) + 1
            old_text, new_text, apart = text, text, None
            if translate and root == old_shipped:
                new_text, bad = v1_to_v2(text)
                apart = "interior section altered (apart)" if interior_changed(text, pool) or bad else None
            elif translate:
                old_text, disordered = v2_to_v1(text)
                apart = "rows out of order (apart)" if disordered else None
            with open(old_path, "w", encoding="utf-8") as f:
                f.write(old_text)
            with open(new_path, "w", encoding="utf-8") as f:
                f.write(new_text)
            compare(["--file", old_path], ["--file", new_path], "mutant %d in %s (%s)" % (n, fmt, ", ".join(what)),
                    apart)

    # (c) mutations of a manifest (a copy of the variants set; OLD's copy gets the same edit,
    # its own hashes in place of NEW's)
    odir, ndir = os.path.join(tmp, "old-variants"), os.path.join(tmp, "variants")
    shutil.copytree(os.path.join(old_shipped, "variants"), odir)
    shutil.copytree(os.path.join(SHIPPED, "variants"), ndir)
    manifest = open(os.path.join(SHIPPED, "variants", "manifest"), encoding="utf-8").read()
    old_manifest = open(os.path.join(old_shipped, "variants", "manifest"), encoding="utf-8").read()
    hashes = dict(zip(re.findall(r"fnv1a64 ([0-9a-f]{16})", manifest), re.findall(r"fnv1a64 ([0-9a-f]{16})", old_manifest)))
    for n in range(max(mutants // 20, 10)):
        _, text = mutate(manifest, rng)
        with open(os.path.join(ndir, "manifest"), "w", encoding="utf-8") as f:
            f.write(text)
        with open(os.path.join(odir, "manifest"), "w", encoding="utf-8") as f:
            f.write(re.sub(r"\b[0-9a-f]{16}\b", lambda m: hashes.get(m.group(), m.group()), text))
        compare([os.path.join(odir, "manifest")], [os.path.join(ndir, "manifest")], "manifest mutant %d" % n)
    shutil.rmtree(tmp)
    print("shipped inputs: %d; mutants by first mutation: %s" % (shipped, kinds))
    print("; ".join("%s %d" % kv for kv in tally.items()))
    return 1 if tally["verdict differs"] else 0


def interior_changed(text, pool):
    """Whether a format-1 mutant's interior sections (header and id lines) are not all verbatim
    those of seed certificates."""
    def sections(t):
        out, lines = [], [tokens(l) for l in t.split("\n")]
        lines = [l for l in lines if l]
        for i, l in enumerate(lines):
            if l[0] == "interior":
                body, j = list(l), i + 1
                while len(l) == 2 and is_int(l[1]) and len(body) - 2 < int(l[1]) and j < len(lines):
                    body += lines[j]
                    j += 1
                out.append(" ".join(body))
        return out
    known = set(sum((sections(c) for c in pool), []))
    return any(s not in known for s in sections(text))


if __name__ == "__main__":
    sys.exit(main())
