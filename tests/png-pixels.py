#!/usr/bin/env python3
"""Check pixels of a figure rasterised by rsvg-convert (tests/cli-draw.sh).

Usage: png-pixels.py FIGURE.png FIGURE.svg CHECK...
where each CHECK is X,Y,DX,DY,dark or X,Y,DX,DY,light: the point (X, Y)
of the part's plane, mapped to pixels by the figure's own transform (the
data-x0, data-y0 and data-scale of its <g class="plane">), then moved by
(DX, DY) pixels.  dark: some pixel within one pixel of it is dark
(luminance below 90 of 255); light: none is.  Standard library only: the
PNG is decoded here (8-bit RGB or RGBA, not interlaced).

png-pixels.py --nonblank N IMAGE.png: at least N dark pixels (a
screenshot that shows something)."""
import re, struct, sys, zlib

def read_png(path, width=None, height=None):
    """(w, h, bpp, rows): the image's size and its rows of bytes.  Only
    the top-left width x height pixels are decoded (a pixel depends on
    those above and left of it only), the rest of each row left as zeros."""
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
    pos, idat, w = 8, b'', None
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', body)
            assert depth == 8 and ctype in (2, 6) and interlace == 0, 'unsupported PNG'
            bpp = 3 if ctype == 2 else 4
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, stride = zlib.decompress(idat), w * bpp
    n = min(w, width if width is not None else w) * bpp
    rows, prev = [], bytearray(n)
    low7, high = int.from_bytes(b'\x7f' * n, 'big'), int.from_bytes(b'\x80' * n, 'big')
    for y in range(min(h, height if height is not None else h)):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:y * (stride + 1) + 1 + n])
        if f == 2:
            # every byte plus the one above it, mod 256, in one big-integer sum
            a, b = int.from_bytes(line, 'big'), int.from_bytes(prev, 'big')
            line = bytearray((((a & low7) + (b & low7)) ^ ((a ^ b) & high)).to_bytes(n, 'big'))
        elif f != 0:
            for i in range(n):
                a = line[i - bpp] if i >= bpp else 0
                b, c = prev[i], prev[i - bpp] if i >= bpp else 0
                if f == 1: line[i] = (line[i] + a) & 255
                elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
                elif f == 4:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line + bytearray(stride - n))
        prev = line
    return w, h, bpp, rows

def lum(rows, bpp, x, y):
    p = rows[y][x * bpp:x * bpp + bpp]
    alpha = p[3] / 255 if bpp == 4 else 1
    # over white
    return sum((0.299, 0.587, 0.114)[k] * (p[k] * alpha + 255 * (1 - alpha)) for k in range(3))

if sys.argv[1] == '--nonblank':
    w, h, bpp, rows = read_png(sys.argv[3])
    dark = sum(1 for y in range(0, h, 3) for x in range(0, w, 3) if lum(rows, bpp, x, y) < 90)
    if dark < int(sys.argv[2]):
        print('%s: %d dark pixels, want at least %s' % (sys.argv[3], dark, sys.argv[2]))
        sys.exit(1)
    sys.exit(0)
svg = open(sys.argv[2]).read()
m = re.search(r'<g class="plane" data-x0="([-0-9.]+)" data-y0="([-0-9.]+)" data-scale="([-0-9.]+)"', svg)
x0, y0, s = map(float, m.groups())
checks = []
for check in sys.argv[3:]:
    x, y, dx, dy, want = check.split(',')
    checks.append((x, y, want, round(x0 + s * float(x) + float(dx)),
                   round(y0 - s * float(y) + float(dy))))
w, h, bpp, rows = read_png(sys.argv[1], max(c[3] for c in checks) + 2,
                           max(c[4] for c in checks) + 2)
bad = 0
for x, y, want, px, py in checks:
    darkest = min(lum(rows, bpp, i, j) for i in range(px - 1, px + 2)
                  for j in range(py - 1, py + 2) if 0 <= i < w and 0 <= j < h)
    if (darkest < 90) != (want == 'dark'):
        print('%s: pixel (%d, %d) of plane point (%s, %s) is not %s (luminance %.0f)'
              % (sys.argv[1], px, py, x, y, want, darkest))
        bad += 1
sys.exit(1 if bad else 0)
