#!/usr/bin/env python3
"""compare_states.py: compare two files of `state` answers, line by line.

    python3 compare_states.py EXPECTED.states MINE.states [--rel 1e-9] [--floor 1e-12]

Each line is one answer: X Y Z VX VY VZ WX WY WZ [QW QX QY QZ]. The numbers are
compared in their groups (position, velocity, angular velocity, quaternion): a number
matches when |a - b| <= rel * max(scale, floor), where scale is the largest |value|
of that group in either file's line. Where one line has the quaternion and the other
has not, the first 9 numbers are compared. Quaternions are compared as written
(q and -q are not treated as equal).

Exit status: 0 every number matches, 1 some do not (each mismatch is listed),
2 bad input (a file that cannot be read, a line that is not numbers, a different
number of lines).
"""
import argparse
import math
import sys

GROUPS = [("x", 0, 3), ("v", 3, 6), ("omega", 6, 9), ("r", 9, 13)]


def read_states(path):
    try:
        with open(path) as f:
            lines = [line.split() for line in f if line.strip()]
    except OSError as error:
        sys.stderr.write("compare_states.py: %s\n" % error)
        sys.exit(2)
    result = []
    for k, tokens in enumerate(lines, start=1):
        if len(tokens) not in (9, 13):
            sys.stderr.write("compare_states.py: %s: answer %d has %d numbers, expected 9 or 13: %s\n"
                             % (path, k, len(tokens), " ".join(tokens)))
            sys.exit(2)
        try:
            result.append([float(t) for t in tokens])
        except ValueError:
            sys.stderr.write("compare_states.py: %s: answer %d is not numbers: %s\n" % (path, k, " ".join(tokens)))
            sys.exit(2)
    return result


def main():
    parser = argparse.ArgumentParser(description="Compare two files of state answers.")
    parser.add_argument("expected")
    parser.add_argument("mine")
    parser.add_argument("--rel", type=float, default=1e-9, help="relative tolerance (default 1e-9)")
    parser.add_argument("--floor", type=float, default=1e-12,
                        help="smallest scale a group is measured against (default 1e-12)")
    args = parser.parse_args()
    expected = read_states(args.expected)
    mine = read_states(args.mine)
    if len(expected) != len(mine):
        sys.stderr.write("compare_states.py: %s has %d answers, %s has %d\n"
                         % (args.expected, len(expected), args.mine, len(mine)))
        return 2
    mismatches = 0
    worst = 0.0
    for k, (a, b) in enumerate(zip(expected, mine), start=1):
        count = min(len(a), len(b))
        for name, lo, hi in GROUPS:
            if hi > count:
                continue
            values = a[lo:hi] + b[lo:hi]
            if not all(math.isfinite(v) for v in values):
                print("answer %d, %s: not finite: %s vs %s" % (k, name, a[lo:hi], b[lo:hi]))
                mismatches += 1
                continue
            scale = max(max(abs(v) for v in values), args.floor)
            diff = max(abs(p - q) for p, q in zip(a[lo:hi], b[lo:hi]))
            worst = max(worst, diff / scale)
            if diff > args.rel * scale:
                print("answer %d, %s: %s vs %s (difference %.3g, %.3g of the scale)"
                      % (k, name, a[lo:hi], b[lo:hi], diff, diff / scale))
                mismatches += 1
    print("%d answers, %d mismatches, worst relative difference %.3g (tolerance %g)"
          % (len(expected), mismatches, worst, args.rel))
    return 1 if mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
