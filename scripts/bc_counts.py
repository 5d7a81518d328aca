#!/usr/bin/env python3
"""Instruction slots of hfx's D3D9 shaders against fxc's, shader by shader, for effects whose
fxc binaries sit beside their sources (FNA's stock effects: HLSL/X.fx and FXB/X.fxb):
    scripts/bc_counts.py BUILD_DIR SRC_DIR FXB_DIR [Effect...]
Both are listed by `hfxc --disassemble`; a shader is named by its effect and its array slot
(VSArray[3]) or its technique / pass. Prints one row per shader and the totals."""
import os, re, subprocess, sys, tempfile

def slots(listing):
    """{shader name: slots} from a disassembly: the '// NAME' or 'asm {' heading each shader."""
    out, name = {}, None
    for line in listing.splitlines():
        m = re.match(r'\s*// (\w+\[\d+\])\s*$', line)
        if m: name = m.group(1)
        m = re.search(r'approximately (\d+) instruction slots used', line)
        if m and name:
            out[name] = int(m.group(1))
            name = None
    return out

def listing(hfxc, path):
    r = subprocess.run([hfxc, '--disassemble', path], capture_output=True, text=True)
    return r.stdout

def main():
    build, src, fxb = sys.argv[1:4]
    hfxc = os.path.join(build, 'compiler', 'hfxc')
    names = sys.argv[4:] or sorted(f[:-4] for f in os.listdir(fxb) if f.endswith('.fxb'))
    tot_h = tot_f = at_or_under = rows = 0
    with tempfile.TemporaryDirectory() as tmp:
        for n in names:
            theirs = slots(listing(hfxc, os.path.join(fxb, n + '.fxb')))
            out = os.path.join(tmp, n + '.fxo')
            r = subprocess.run([hfxc, '/T', 'fx_2_0', '/Fo', out, os.path.join(src, n + '.fx')], capture_output=True, text=True)
            ours = slots(listing(hfxc, out)) if r.returncode == 0 else {}
            if r.returncode: print(n, 'fails:', (r.stderr.strip().splitlines() or ['?'])[0])
            for k in sorted(theirs, key=lambda s: (s[:2], int(re.search(r'\d+', s).group()))):
                h, f = ours.get(k), theirs[k]
                rows += 1
                mark = '' if h is None else ' ' if h <= f else ' +%d' % (h - f)
                print('%-22s %-14s hfx %4s fxc %4d%s' % (n, k, '-' if h is None else h, f, mark))
                tot_f += f
                if h is not None:
                    tot_h += h
                    at_or_under += h <= f
    print('%d shaders, hfx at or under fxc in %d; total hfx %d, fxc %d' % (rows, at_or_under, tot_h, tot_f))

main()
