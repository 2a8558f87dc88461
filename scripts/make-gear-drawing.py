#!/usr/bin/env python3
"""Writes examples/drawings/gear-in-ring.dxf, the DXF drawing `cslice import` reads in the main
job: a spur gear of 8 straight-flanked teeth (layer GEAR, one closed polyline with bulges)
inside a ring gear of 16 teeth (layer RING, loose lines and arcs as a CAD program leaves them
after trimming), plus a title and centre lines that are not outline (ignored). Module 1 mm.
The drawing is committed; this script only documents how it was made (python3, no modules)."""
import math

def teeth(z, tip, root, tip_half, root_half, phase):
    """Vertices (x, y, bulge) of a gear outline, counterclockwise about the origin."""
    pitch = 2 * math.pi / z
    out = []
    for i in range(z):
        c = phase + i * pitch
        at = lambda r, a, sweep: (r * math.cos(a), r * math.sin(a), math.tan(sweep / 4))
        out.append(at(root, c - root_half, 0.0))
        out.append(at(tip, c - tip_half, 2 * tip_half))
        out.append(at(tip, c + tip_half, 0.0))
        out.append(at(root, c + root_half, pitch - 2 * root_half))
    return out

groups = []
def g(code, value):
    groups.append("%3d" % code)
    groups.append(value if isinstance(value, str) else repr(float(value)))

g(0, "SECTION"); g(2, "HEADER"); g(9, "$INSUNITS"); g(70, "4"); g(0, "ENDSEC")
g(0, "SECTION"); g(2, "ENTITIES")
# The gear: module 1, 8 teeth, tip radius 5, root radius 2.75.
p = 2 * math.pi / 8
gear = teeth(8, 5.0, 2.75, 0.126 * p, 0.2625 * p, 0.0)
g(0, "LWPOLYLINE"); g(8, "GEAR"); g(90, str(len(gear))); g(70, "1")
for x, y, b in gear:
    g(10, x); g(20, y)
    if b != 0.0: g(42, b)
# The ring: 16 internal teeth, tips at radius 7, roots at 9.25, as separate entities.
p = 2 * math.pi / 16
ring = teeth(16, 7.0, 9.25, 0.2625 * p, 0.126 * p, p / 2)
for k, (x, y, b) in enumerate(ring):
    nx, ny, _ = ring[(k + 1) % len(ring)]
    if b == 0.0:
        g(0, "LINE"); g(8, "RING"); g(10, x); g(20, y); g(11, nx); g(21, ny)
    else:
        r = math.hypot(x, y)
        a0 = math.degrees(math.atan2(y, x)); a1 = math.degrees(math.atan2(ny, nx))
        g(0, "ARC"); g(8, "RING"); g(10, 0.0); g(20, 0.0); g(40, r); g(50, a0); g(51, a1)
# Annotation: centre lines and a title, on their own layers.
g(0, "LINE"); g(8, "CENTER"); g(10, -11.0); g(20, 0.0); g(11, 11.0); g(21, 0.0)
g(0, "LINE"); g(8, "CENTER"); g(10, 0.0); g(20, -11.0); g(11, 0.0); g(21, 11.0)
g(0, "TEXT"); g(8, "TITLE"); g(10, -10.0); g(20, -12.0); g(40, 0.8); g(1, "8-tooth gear in a 16-tooth ring, module 1")
g(0, "ENDSEC"); g(0, "EOF")
with open("examples/drawings/gear-in-ring.dxf", "w", newline="\r\n") as f:
    f.write("\n".join(groups) + "\n")
