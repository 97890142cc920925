#!/usr/bin/env python3
"""Writes the curved-part example (README "Normal deviation"): a ball cutter R = 1 mm
finishing a convex cylinder of radius 10 mm (axis along x, top at z = 0) in passes along
its axis, the tool axis along the surface normal, 3 degrees apart from -72 to +72
degrees (zigzag; the connecting moves turn the axis beyond the part's ends). Between two
passes the normal deviation peaks at the closed-form cusp: the balls' centres lie on
radius 11 mm, 3 degrees apart, so the cusp is 11 cos(1.5 deg) - sqrt(1 - (11 sin(1.5
deg))^2) - 10 = 0.03858 mm above the cylinder.

  examples/cylinder_ball.txt     the CL path: x y z i j k (tip and axis) a line
  examples/cylinder_design.stl   the design: the cylinder over x in [0, 4] mm and
                                 -72..72 degrees, facets every 1 mm and 0.5 degree
"""
import math
import struct

RHO, R = 10.0, 1.0


def surface(x, deg):
    t = math.radians(deg)
    return (x, RHO * math.sin(t), -RHO + RHO * math.cos(t)), (0.0, math.sin(t), math.cos(t))


with open("cylinder_ball.txt", "w") as f:
    f.write("# Ball R1 along a cylinder of radius 10 (examples/cylinder_ball_make.py)\n")
    for k, deg in enumerate(range(-72, 73, 3)):
        xs = (-2.0, 6.0) if k % 2 == 0 else (6.0, -2.0)
        for x in xs:
            p, n = surface(x, deg)
            f.write("%.9f %.9f %.9f %.12f %.12f %.12f\n" % (p + n))

facets = []
for i in range(4):
    for j in range(288):
        a0, a1 = -72 + 0.5 * j, -72 + 0.5 * (j + 1)
        p00, p10 = surface(i, a0)[0], surface(i + 1, a0)[0]
        p01, p11 = surface(i, a1)[0], surface(i + 1, a1)[0]
        # Counter-clockwise seen from outside (the normal points away from the axis).
        facets.append((p00, p10, p01))
        facets.append((p10, p11, p01))
with open("cylinder_design.stl", "wb") as f:
    f.write(b"cylinder R10, x 0..4, -72..72 deg (examples/cylinder_ball_make.py)".ljust(80, b" "))
    f.write(struct.pack("<I", len(facets)))
    for a, b, c in facets:
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        length = math.sqrt(sum(q * q for q in n))
        f.write(struct.pack("<12fH", *[q / length for q in n], *a, *b, *c, 0))
