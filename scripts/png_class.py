#!/usr/bin/env python3
# png_class.py PNG...: for each hfxview picture, "drawn", "black" or "blank" and the path:
# blank when every pixel is the background (XNA's CornflowerBlue, within 2/255), black when
# the pixels that differ from it are all black (no channel above 10/255), drawn otherwise.
# scripts/corpus.sh techniques uses it; the standard library only (zlib), no imaging package.
import sys, zlib, struct
def read_png(path):
    d = open(path,'rb').read()
    assert d[:8] == b'\x89PNG\r\n\x1a\n'
    pos = 8; idat = b''; w=h=0
    while pos < len(d):
        n, = struct.unpack('>I', d[pos:pos+4]); t = d[pos+4:pos+8]; c = d[pos+8:pos+8+n]; pos += 12+n
        if t == b'IHDR': w,h,bd,ct,_,_,il = struct.unpack('>IIBBBBB', c)
        elif t == b'IDAT': idat += c
    bpp = {2:3, 6:4}[ct]; raw = zlib.decompress(idat); stride = w*bpp
    rows = []; prev = bytearray(stride); i = 0
    for y in range(h):
        f = raw[i]; line = bytearray(raw[i+1:i+1+stride]); i += 1+stride
        for x in range(stride):
            a = line[x-bpp] if x >= bpp else 0; b = prev[x]; c = prev[x-bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x]+a) & 255
            elif f == 2: line[x] = (line[x]+b) & 255
            elif f == 3: line[x] = (line[x]+((a+b)>>1)) & 255
            elif f == 4:
                p = a+b-c; pa, pb, pc = abs(p-a), abs(p-b), abs(p-c)
                line[x] = (line[x] + (a if pa<=pb and pa<=pc else b if pb<=pc else c)) & 255
        rows.append(line); prev = line
    return w, h, bpp, rows
BG = (100,149,237)
def classify(path):
    try: w,h,bpp,rows = read_png(path)
    except Exception: return 'missing'
    differ = 0; lit = 0
    for r in rows:
        for x in range(w):
            p = r[x*bpp:x*bpp+3]
            if max(abs(p[0]-BG[0]),abs(p[1]-BG[1]),abs(p[2]-BG[2])) > 2:
                differ += 1
                if max(p) > 10: lit += 1
    if differ == 0: return 'blank'
    if lit == 0: return 'black'
    return 'drawn'
if __name__ == '__main__':
    for p in sys.argv[1:]:
        print(classify(p), p)
