#!/usr/bin/env python3
"""xnb_effects.py: fxc's fx_2_0 effects out of XNA's compiled content, for scripts/fx2_oracle.sh.

    scripts/xnb_effects.py FOLDER

XNA 3.x builds every .fx of a game's Content project with fxc and keeps the result in
bin/<platform>/<configuration>/Content/NAME.xnb: an uncompressed XNB file whose primary object is
read by Microsoft.Xna.Framework.Content.EffectReader (a byte count, then the fx_2_0 effect).
Each such file under FOLDER becomes Content/NAME.fxo beside Content/NAME.fx (the bin/... part of
its path dropped), so fx2_oracle.sh pairs it with its source; files that hold other content,
compressed ones (XNA 4's LZX) and ones without a source are left out, with a line saying why.
The .xnb files are removed once read. Run it on a copy extracted outside the repository.
"""
import os
import struct
import sys

FX2 = bytes([1, 9, 0xFF, 0xFE])


def seven_bit(d, at):
    """A 7-bit encoded int (.NET's BinaryReader) at d[at]: (value, next offset)."""
    v = shift = 0
    while True:
        b = d[at]
        at += 1
        v |= (b & 0x7F) << shift
        shift += 7
        if not b & 0x80:
            return v, at


def effect_of(d):
    """The fx_2_0 bytes of an XNB file whose primary object is an effect, or a reason it has none."""
    if len(d) < 10 or d[:3] != b"XNB":
        return None, "not an XNB file"
    if d[5] & 0x80:
        return None, "compressed (XNA 4 LZX)"
    at = 10
    readers = []
    count, at = seven_bit(d, at)
    for _ in range(count):
        n, at = seven_bit(d, at)
        readers.append(d[at:at + n].decode("utf-8", "replace"))
        at += n + 4  # the reader's version
    _, at = seven_bit(d, at)  # shared resources
    index, at = seven_bit(d, at)
    if index == 0 or not readers[index - 1].startswith("Microsoft.Xna.Framework.Content.EffectReader"):
        return None, "not an effect"
    size = struct.unpack("<I", d[at:at + 4])[0]
    blob = d[at + 4:at + 4 + size]
    return (blob, None) if blob[:4] == FX2 else (None, "no fx_2_0 effect inside")


def beside_source(path):
    """bin/x86/Debug/Content/NAME.xnb -> Content/NAME.fxo (the folder the .fx is in)."""
    parts = path.split(os.sep)
    if "bin" in parts:
        i = parts.index("bin")
        rest = parts[i + 1:]
        while len(rest) > 1 and rest[0] in ("x86", "Xbox 360", "Zune", "Debug", "Release"):
            rest = rest[1:]
        parts = parts[:i] + rest
    return os.sep.join(parts)[:-4] + ".fxo"


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: scripts/xnb_effects.py FOLDER")
    written = 0
    for root, _, files in os.walk(sys.argv[1]):
        for f in sorted(files):
            if not f.endswith(".xnb"):
                continue
            path = os.path.join(root, f)
            with open(path, "rb") as fh:
                blob, why = effect_of(fh.read())
            os.remove(path)
            out = beside_source(path)
            if blob is not None and not os.path.exists(out[:-4] + ".fx"):
                blob, why = None, "no source " + out[:-4] + ".fx"
            if blob is None:
                if why != "not an effect":
                    print(f"{path}: {why}")
                continue
            with open(out, "wb") as fh:
                fh.write(blob)
            written += 1
    print(f"{written} effects written")


if __name__ == "__main__":
    main()
