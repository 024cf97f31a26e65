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

def read_png(path):
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
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
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
w, h, bpp, rows = read_png(sys.argv[1])
svg = open(sys.argv[2]).read()
m = re.search(r'<g class="plane" data-x0="([-0-9.]+)" data-y0="([-0-9.]+)" data-scale="([-0-9.]+)"', svg)
x0, y0, s = map(float, m.groups())
bad = 0
for check in sys.argv[3:]:
    x, y, dx, dy, want = check.split(',')
    px, py = round(x0 + s * float(x) + float(dx)), round(y0 - s * float(y) + float(dy))
    darkest = min(lum(rows, bpp, i, j) for i in range(px - 1, px + 2)
                  for j in range(py - 1, py + 2) if 0 <= i < w and 0 <= j < h)
    if (darkest < 90) != (want == 'dark'):
        print('%s: pixel (%d, %d) of plane point (%s, %s) is not %s (luminance %.0f)'
              % (sys.argv[1], px, py, x, y, want, darkest))
        bad += 1
sys.exit(1 if bad else 0)
