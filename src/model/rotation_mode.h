#pragma once
// The keys of a track in its rotation mode (scene.h's RotationMode): the invariant between a key's stored angles
// and its orientation, and the conversion of the keys from one mode to another.
//
// The invariant, kept in one place (DocumentEditor, after every edit of keys or track settings): in Euler mode
// every key has angles and pose.orientation == quaternionFromEulerAngles(angles, convention) to rounding; in
// quaternion mode no key has angles. An edit that set a key's orientation alone (a rotate handle, a paste from a
// quaternion object, a fit that moved a free key, a screw edit) leaves angles that no longer give it: the key
// gets the angles of its new orientation nearest its old angles, or nearest the previous key's when it had none.

#include "model/scene.h"

#include <Eigen/Geometry>

#include <vector>

namespace gyre::model {

// How far, as |q − p| or |q + p|, a key's orientation may be from the one its angles give: rounding.
inline constexpr double kEulerAnglesTolerance = 1e-9;

// Whether the angles give the orientation, to kEulerAnglesTolerance.
bool anglesGiveOrientation(const Eigen::Vector3d& angles, const Eigen::Quaterniond& orientation,
                           const EulerConvention& convention);

// Whether the track's keys hold the invariant of its rotation mode.
bool keepsRotationMode(const MotionTrack& track);

// Restores the invariant of the track's rotation mode (above). Touches the keys (and so copies shared ones) only
// when some key breaks it.
void keepRotationMode(MotionTrack& track);

// The track's keys held in `mode`: to Euler, each key's orientation as the Euler filter unwraps them along the keys
// in the new convention (a key already in Euler mode in the same convention keeps its angles); to quaternion, the
// orientations as they are. The orientations never change.
std::vector<Keyframe> keysInRotationMode(const MotionTrack& track, const RotationMode& mode);

// The interpolation a track takes on entering `mode` from its `current` one: euler-cubic entering Euler mode,
// hermite leaving it, `current` otherwise.
InterpolationMethod interpolationInRotationMode(InterpolationMethod current, const RotationMode& from,
                                                const RotationMode& to);

// The import option "Euler filter": a track as read from a scene file (quaternion keys) put in Euler mode in
// `convention`, its keys' angles the Euler filter's (keysInRotationMode), so that a spin the file stored wrapped
// is a ramp. Slerp keys (a file's linear keys) become euler, linear on the angles as a DCC's Euler curves are;
// others take interpolationInRotationMode's. The orientations at the keys do not change.
void putInEulerMode(MotionTrack& track, const EulerConvention& convention);

} // namespace gyre::model
