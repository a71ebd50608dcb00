#include "model/rotation_mode.h"

#include <algorithm>
#include <optional>

namespace gyre::model {

bool anglesGiveOrientation(const Eigen::Vector3d& angles, const Eigen::Quaterniond& orientation,
                           const EulerConvention& convention)
{
    const Eigen::Vector4d given = quaternionFromEulerAngles(angles, convention).coeffs();
    const Eigen::Vector4d stored = orientation.normalized().coeffs();
    // q and −q are the same rotation.
    return std::min((given - stored).norm(), (given + stored).norm()) <= kEulerAnglesTolerance;
}

namespace {

bool keyKeepsMode(const Keyframe& key, const RotationMode& mode)
{
    if (!mode.isEuler())
        return !key.eulerAngles.has_value();
    return key.eulerAngles && key.eulerAngles->allFinite() &&
           anglesGiveOrientation(*key.eulerAngles, key.pose.orientation, mode.convention);
}

} // namespace

bool keepsRotationMode(const MotionTrack& track)
{
    for (const Keyframe& key : track.keys)
        if (!keyKeepsMode(key, track.rotationMode))
            return false;
    return true;
}

void keepRotationMode(MotionTrack& track)
{
    if (keepsRotationMode(track))
        return;
    const RotationMode& mode = track.rotationMode;
    std::optional<Eigen::Vector3d> previous;
    for (Keyframe& key : track.keys.edit()) {
        if (!keyKeepsMode(key, mode)) {
            if (!mode.isEuler()) {
                key.eulerAngles.reset();
            } else {
                const Eigen::Vector3d angles = eulerAnglesFromQuaternion(key.pose.orientation, mode.convention).angles;
                const std::optional<Eigen::Vector3d> near =
                    key.eulerAngles && key.eulerAngles->allFinite() ? key.eulerAngles : previous;
                key.eulerAngles = near ? nearestEquivalentAngles(angles, *near, mode.convention) : angles;
            }
        }
        previous = key.eulerAngles;
    }
}

std::vector<Keyframe> keysInRotationMode(const MotionTrack& track, const RotationMode& mode)
{
    std::vector<Keyframe> keys = track.keys;
    if (!mode.isEuler()) {
        for (Keyframe& key : keys)
            key.eulerAngles.reset();
        return keys;
    }
    if (track.rotationMode == mode)
        return keys;
    std::vector<Eigen::Quaterniond> rotations;
    rotations.reserve(keys.size());
    for (const Keyframe& key : keys)
        rotations.push_back(key.pose.orientation);
    const std::vector<Eigen::Vector3d> angles = unwrappedEulerAngles(rotations, mode.convention);
    for (std::size_t i = 0; i < keys.size(); ++i)
        keys[i].eulerAngles = angles[i];
    return keys;
}

InterpolationMethod interpolationInRotationMode(InterpolationMethod current, const RotationMode& from,
                                                const RotationMode& to)
{
    if (to.isEuler() && !from.isEuler())
        return InterpolationMethod::EulerCubic;
    if (!to.isEuler() && from.isEuler())
        return InterpolationMethod::Hermite;
    return current;
}

void putInEulerMode(MotionTrack& track, const EulerConvention& convention)
{
    const RotationMode mode{RotationMode::Kind::Euler, convention};
    track.keys = keysInRotationMode(track, mode);
    track.interpolation = track.interpolation == InterpolationMethod::Slerp
                              ? InterpolationMethod::Euler
                              : interpolationInRotationMode(track.interpolation, track.rotationMode, mode);
    track.rotationMode = mode;
}

} // namespace gyre::model
