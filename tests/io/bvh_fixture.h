#pragma once
// A BVH motion-capture file written in code: a chain of joints, each turning about z, x, y (in that
// channel order) by angles known in closed form, the root also moving. For the import test and for
// gyre-bench, which must make their fixtures themselves.

#include <QByteArray>

#include <cmath>
#include <cstdio>
#include <string>

namespace gyre::test {

// The angle in degrees of channel `axis` (0 = Zrotation, 1 = Xrotation, 2 = Yrotation) of `joint`
// at `frame`: within ±60°, different for every joint, axis and frame.
inline double bvhAngleDegrees(int joint, int frame, int axis)
{
    return 60.0 * std::sin(0.05 * frame * (axis + 1) + 0.7 * joint + axis);
}

// The root's position at `frame`.
inline double bvhRootX(int frame) { return 0.25 * frame; }

inline constexpr double kBvhBoneLength = 2.0; // each joint's offset along y from its parent

// `joints` joints in a chain named joint0 (the root), joint1, …; `frames` frames `frameTime` apart.
inline QByteArray bvhChain(int joints, int frames, double frameTime)
{
    std::string text = "HIERARCHY\n";
    for (int j = 0; j < joints; ++j) {
        text += (j == 0 ? "ROOT joint" : "JOINT joint") + std::to_string(j) + "\n{\n";
        text += j == 0 ? "OFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                       : "OFFSET 0 " + std::to_string(kBvhBoneLength) + " 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
    }
    text += "End Site\n{\nOFFSET 0 1 0\n}\n";
    for (int j = 0; j < joints; ++j)
        text += "}\n";
    char number[32];
    std::snprintf(number, sizeof number, "%.17g", frameTime);
    text += "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: " + number + "\n";
    for (int k = 0; k < frames; ++k) {
        std::snprintf(number, sizeof number, "%.9g 0 0", bvhRootX(k));
        text += number;
        for (int j = 0; j < joints; ++j)
            for (int axis = 0; axis < 3; ++axis) {
                std::snprintf(number, sizeof number, " %.9g", bvhAngleDegrees(j, k, axis));
                text += number;
            }
        text += '\n';
    }
    return QByteArray::fromStdString(text);
}

} // namespace gyre::test
