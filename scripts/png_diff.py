#!/usr/bin/env python3
# png_diff.py A.png B.png [A2.png B2.png ...]: for each pair, the largest difference of any
# channel (RGBA, 0..255) between two pictures of the same size and how many pixels differ by
# more than 2/255 in some channel, printed as "MAX COUNT" a line; "size" when the sizes
# differ, "missing" when one cannot be read.
# scripts/fx2_oracle.sh uses it; the standard library only (png_class.py's reader).
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_class import read_png

def diff(a_path, b_path):
    try:
        wa, ha, ba, ra = read_png(a_path)
        wb, hb, bb, rb = read_png(b_path)
    except Exception:
        return 'missing'
    if (wa, ha, ba) != (wb, hb, bb):
        return 'size'
    worst = 0
    count = 0
    for la, lb in zip(ra, rb):
        for x in range(0, len(la), ba):
            m = max(abs(la[x + c] - lb[x + c]) for c in range(ba))
            if m > worst: worst = m
            if m > 2: count += 1
    return f'{worst} {count}'

if __name__ == '__main__':
    if len(sys.argv) < 3 or len(sys.argv) % 2 == 0:
        sys.exit('usage: png_diff.py A.png B.png [A2.png B2.png ...]')
    for i in range(1, len(sys.argv), 2):
        print(diff(sys.argv[i], sys.argv[i + 1]))
