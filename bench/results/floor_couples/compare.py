#!/usr/bin/env python3
"""q against S/B of the two V85.6 half-domain runs, before and after the rule: the difference every
0.02 of S/B, the RMS difference over the common range, and each run's largest load."""
import bisect
import csv
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def record(name):
    with open(os.path.join(HERE, name)) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith('#')))
    return [float(r['S_over_B']) for r in rows], [float(r['q_kPa']) for r in rows]


def at(curve, s):
    i = bisect.bisect_left(curve[0], s)
    if i <= 0 or i >= len(curve[0]):
        return None
    t = (s - curve[0][i - 1]) / (curve[0][i] - curve[0][i - 1])
    return curve[1][i - 1] + t * (curve[1][i] - curve[1][i - 1])


before, after = record('V85.6_half_before.csv'), record('V85.6_half_after.csv')
end = min(before[0][-1], after[0][-1])
num = den = 0.0
for k in range(2, int(end / 0.005) + 1):
    s = 0.005 * k
    a, b = at(before, s), at(after, s)
    if a is None or b is None:
        continue
    num, den = num + (b - a) ** 2, den + a * a
    if k % 4 == 0:
        print('S/B %.2f  before %7.1f  after %7.1f  %+.2f %%' % (s, a, b, 100 * (b / a - 1)))
print('RMS difference to S/B %.3f: %.2f %%' % (end, 100 * (num / den) ** 0.5))
for name, c in (('before', before), ('after', after)):
    i = max(range(len(c[1])), key=lambda j: c[1][j])
    print('%s: largest q %.1f kPa at S/B %.3f' % (name, c[1][i], c[0][i]))
