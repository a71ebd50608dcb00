#!/usr/bin/env python3
"""Writes a BVH motion capture of any size, for measuring Gyre at scale (docs/file-format.md, "Cost").

The same file as tests/io/bvh_fixture.h's bvhChain: a chain of JOINTS joints, each turning about z, x, y
by angles known in closed form, the root also moving, FRAMES frames at 120 Hz.

    scripts/mocap-bvh.py JOINTS FRAMES OUTPUT.bvh
"""
import math
import sys


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    joints, frames, path = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    with open(path, "w") as out:
        out.write("HIERARCHY\n")
        for j in range(joints):
            out.write(("ROOT joint" if j == 0 else "JOINT joint") + f"{j}\n{{\n")
            out.write("OFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                      if j == 0 else "OFFSET 0 2.000000 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n")
        out.write("End Site\n{\nOFFSET 0 1 0\n}\n" + "}\n" * joints)
        out.write(f"MOTION\nFrames: {frames}\nFrame Time: {'%.17g' % (1.0 / 120.0)}\n")
        for k in range(frames):
            numbers = ["%.9g 0 0" % (0.25 * k)]
            numbers += ["%.9g" % (60.0 * math.sin(0.05 * k * (axis + 1) + 0.7 * j + axis))
                        for j in range(joints) for axis in range(3)]
            out.write(" ".join(numbers) + "\n")


if __name__ == "__main__":
    main()
