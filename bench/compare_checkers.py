#!/usr/bin/env python3
"""Differential check of two builds of the proof checker (proofs/checker/): runs OLD and NEW on
every shipped manifest and certificate file, and on a corpus of seeded mutations of the small
shipped certificates (byte flips, line deletions / duplications / swaps, number changes, several
certificates in one file) and of a copied manifest set; reports any input on which their
verdicts (exit code, VERIFIED or not) or their outputs differ.

    bench/compare_checkers.py OLD_CHECKER NEW_CHECKER [MUTANTS] [SEED]

Exit 0 iff every verdict agrees. A one-off tool for changes to the checker, not a CTest test.
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
    tmp = tempfile.mkdtemp(prefix="dualhex-compare-")
    tally = {"inputs": 0, "verified": 0, "rejected": 0, "verdict differs": 0, "output differs": 0}
    shown = 0

    def compare(args, what):
        nonlocal shown
        a, b = run(old, args), run(new, args)
        tally["inputs"] += 1
        tally["verified" if a[1] else "rejected"] += 1
        if a[:2] != b[:2]:
            tally["verdict differs"] += 1
            print("VERDICT DIFFERS:", what, args, "old", a[:2], "new", b[:2])
        elif a[2].replace(old, "CHECKER") != b[2].replace(new, "CHECKER"):
            tally["output differs"] += 1
            if shown < 10:
                shown += 1
                diff = [(x, y) for x, y in zip(a[2].split("\n"), b[2].split("\n")) if x != y][:2]
                print("output differs:", what, diff)

    # (a) every shipped manifest and every shipped certificate file
    for d in ["", "weak", "variants", "windows", "boundary"]:
        compare([os.path.join(SHIPPED, d, "manifest")], "shipped manifest " + d)
        for f in sorted(os.listdir(os.path.join(SHIPPED, d))):
            if f.endswith(".cert"):
                compare(["--file", os.path.join(SHIPPED, d, f)], "shipped file " + d + "/" + f)
    shipped = tally["inputs"]
    # (b) mutations of the small certificates: the 13 elements, the 4 smallest variant elements,
    # the mask-0 torus, the 2 smallest windows and the smallest weak torus
    seeds = (certificates(os.path.join(SHIPPED, "elements.cert")) +
             smallest(os.path.join(SHIPPED, "variants", "elements.cert"), 4) +
             certificates(os.path.join(SHIPPED, "configurations-000-021.cert"))[:1] +
             smallest(os.path.join(SHIPPED, "windows", "windows-0000-0099.cert"), 2) +
             smallest(os.path.join(SHIPPED, "weak", "configurations-000-033.cert"), 1))
    kinds = {}
    path = os.path.join(tmp, "m.cert")
    for n in range(mutants):
        text = rng.choice(seeds)
        what = []
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            w, text = mutate(text, rng)
            what.append(w)
        if rng.randrange(8) == 0:  # several certificates in one file: resynchronisation
            text = text + rng.choice(seeds) + (mutate(rng.choice(seeds), rng)[1] if rng.randrange(2) else "")
            what.append("+ more certificates")
        kinds[what[0]] = kinds.get(what[0], 0) + 1
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        compare(["--file", path], "mutant %d (%s)" % (n, ", ".join(what)))
    # (c) mutations of a manifest (a copy of the variants set)
    mdir = os.path.join(tmp, "variants")
    shutil.copytree(os.path.join(SHIPPED, "variants"), mdir)
    manifest = open(os.path.join(SHIPPED, "variants", "manifest"), encoding="utf-8").read()
    for n in range(max(mutants // 20, 10)):
        _, text = mutate(manifest, rng)
        with open(os.path.join(mdir, "manifest"), "w", encoding="utf-8") as f:
            f.write(text)
        compare([os.path.join(mdir, "manifest")], "manifest mutant %d" % n)
    shutil.rmtree(tmp)
    print("shipped inputs: %d; mutants by first mutation: %s" % (shipped, kinds))
    print("; ".join("%s %d" % kv for kv in tally.items()))
    return 1 if tally["verdict differs"] else 0


if __name__ == "__main__":
    sys.exit(main())
