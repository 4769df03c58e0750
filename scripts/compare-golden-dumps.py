#!/usr/bin/env python3
# compare-golden-dumps.py BEFORE AFTER NEW_IDS: two dumps of tst_golden_trace's hashed text
# (RBW_DUMP_GOLDEN=<file> build/tests/tst_golden_trace), before and after a change that
# only adds trace rows: exit 0 when every line of BEFORE is in AFTER unchanged and every
# added line is an entry of one of NEW_IDS (comma-separated trace ids). Issue 20.
import sys, subprocess, collections
before, after = sys.argv[1], sys.argv[2]
new_ids = set(sys.argv[3].split(','))
def sorted_lines(p):
    return subprocess.run(['bash','-c',f'LC_ALL=C sort {p}'],capture_output=True,text=True).stdout.splitlines()
b = sorted_lines(before); a = sorted_lines(after)
i = j = 0; missing = 0; added = collections.Counter(); bad_added = []
while i < len(b) or j < len(a):
    if i < len(b) and j < len(a) and b[i] == a[j]: i += 1; j += 1; continue
    if j < len(a) and (i >= len(b) or a[j] < b[i]):
        # an added line: which id?
        rest = a[j].split(' k=',1)[1].split(' ',1)[1]
        ident = rest.split('|',1)[0]
        added[ident] += 1
        if ident not in new_ids: bad_added.append(a[j][:200])
        j += 1; continue
    missing += 1
    if missing <= 5: print('CHANGED or REMOVED:', b[i][:200])
    i += 1
print(f'before: {len(b)} lines, after: {len(a)} lines')
print(f'lines of "before" missing from "after": {missing}')
print('added lines by id:', dict(added))
print('added lines with an old id:', len(bad_added)); [print('  ', x) for x in bad_added[:5]]
sys.exit(1 if missing or bad_added else 0)
