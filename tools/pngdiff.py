#!/usr/bin/env python3
"""Pixel-exact comparison of PNG pairs (standard library only).

    python3 tools/pngdiff.py a.png b.png [c.png d.png ...]
    python3 tools/pngdiff.py --dirs before/ after/      # every *.png in before/ against after/

Prints, per pair, "same" or the number of differing pixels, the largest channel difference and the
first differing pixel; exits 1 when any pair differs. Used to check that a performance change left
every benchmark image untouched (decodes 8-bit greyscale/RGB/RGBA, non-interlaced PNGs: what the
ray tracer and the usual tools write).
"""
import os
import struct
import sys
import zlib


def decode(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s: not a PNG" % path)
    pos, idat, hdr = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        crc = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])[0]
        if zlib.crc32(kind + body) & 0xFFFFFFFF != crc:
            raise ValueError("%s: bad CRC in %s chunk" % (path, kind.decode("latin-1")))
        if kind == b"IHDR":
            hdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
        pos += 12 + length
    w, h, depth, ctype, _, _, interlace = hdr
    if depth != 8 or interlace != 0 or ctype not in (0, 2, 6):
        raise ValueError("%s: only 8-bit non-interlaced grey/RGB/RGBA PNGs are supported" % path)
    bpp = {0: 1, 2: 3, 6: 4}[ctype]
    raw = zlib.decompress(b"".join(idat))
    stride = w * bpp
    out = bytearray(h * stride)
    prev = bytearray(stride)
    p = 0
    for y in range(h):
        ft = raw[p]
        line = bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        if ft == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif ft == 2:
            for i in range(stride):
                line[i] = (line[i] + prev[i]) & 255
        elif ft == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 255
        elif ft == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b = prev[i]
                c = prev[i - bpp] if i >= bpp else 0
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pr) & 255
        elif ft != 0:
            raise ValueError("%s: bad filter type %d" % (path, ft))
        out[y * stride:(y + 1) * stride] = line
        prev = line
    if bpp == 1:
        rgb = bytearray(b for v in out for b in (v, v, v))
    elif bpp == 4:
        rgb = bytearray(out[i] for i in range(len(out)) if i % 4 != 3)
    else:
        rgb = out
    return w, h, rgb


def compare(a, b):
    wa, ha, pa = decode(a)
    wb, hb, pb = decode(b)
    if (wa, ha) != (wb, hb):
        print("%s vs %s: sizes differ (%dx%d vs %dx%d)" % (a, b, wa, ha, wb, hb))
        return False
    if pa == pb:
        print("%s vs %s: same (%dx%d)" % (a, b, wa, ha))
        return True
    diff, worst, first = 0, 0, None
    for i in range(0, len(pa), 3):
        d = max(abs(pa[i + k] - pb[i + k]) for k in range(3))
        if d:
            diff += 1
            worst = max(worst, d)
            if first is None:
                first = (i // 3 % wa, i // 3 // wa)
    print("%s vs %s: %d pixels differ, largest channel difference %d, first at %s" % (a, b, diff, worst, first))
    return False


def main(args):
    if args[:1] == ["--dirs"]:
        da, db = args[1], args[2]
        names = sorted(n for n in os.listdir(da) if n.endswith(".png"))
        pairs = [(os.path.join(da, n), os.path.join(db, n)) for n in names]
    else:
        if len(args) < 2 or len(args) % 2:
            print(__doc__.strip())
            return 2
        pairs = list(zip(args[0::2], args[1::2]))
    ok = all([compare(a, b) for a, b in pairs])
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
