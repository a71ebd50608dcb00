#pragma once
// The channels of a track over time, as the graph editor plots them: the orientation as
// three Euler angles in a chosen convention, unwrapped along time (the Euler filter,
// core/euler_angles.h) so that a spin is a ramp and not a saw-tooth; the orientation as the four
// quaternion components, their sign kept continuous from the first key's; the angular velocity's
// components in the parent's (world) or the object's own (local) frame and its magnitude; and the
// position; and, for the physics, the angular momentum L = R·I·Rᵀ·ω about the centre of mass and the
// rotational kinetic energy ½·ωᵀ·R·I·Rᵀ·ω, with R the orientation and I the body's inertia tensor
// (model/object_mass.h): in free flight both stay constant. Where the middle angle comes near its gimbal-lock value, the time spans are listed, since
// there the first and third angles stop meaning much on their own.

#include "core/euler_angles.h"
#include "model/track_evaluation.h"

#include <array>
#include <cstddef>
#include <numbers>
#include <utility>
#include <vector>

namespace gyre::model {

enum class Channel {
    EulerFirst,
    EulerSecond,
    EulerThird,
    QuaternionW,
    QuaternionX,
    QuaternionY,
    QuaternionZ,
    AngularVelocityX,
    AngularVelocityY,
    AngularVelocityZ,
    AngularSpeed,
    PositionX,
    PositionY,
    PositionZ,
    AngularMomentumX,
    AngularMomentumY,
    AngularMomentumZ,
    AngularMomentumMagnitude,
    KineticEnergy,
};
inline constexpr std::size_t kChannelCount = 19;

inline bool isEulerChannel(Channel channel) { return channel <= Channel::EulerThird; }
// 0, 1 or 2 for the first, second and third Euler angle.
inline int eulerIndex(Channel channel) { return static_cast<int>(channel); }

// The frame angular velocity and momentum are given in: the parent's (ω = 2q′q⁻¹) or the object's own
// (ω_local = q⁻¹ ω q, what a gyroscope on the object reads; L_local = I·ω_local).
enum class VelocityFrame { World, Local };

// Within this distance of gimbal lock a change δ of the rotation can move the first and third angles
// by δ / sin(5°), more than eleven times as much: the span is shaded.
inline constexpr double kGimbalZoneRadians = 5.0 * std::numbers::pi / 180.0;

struct ChannelSettings {
    EulerConvention convention;
    VelocityFrame velocityFrame = VelocityFrame::World;
    double start = 0.0; // seconds
    double end = 10.0;
    std::size_t samples = 2000; // evenly spaced from start to end, besides the keys' times
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity(); // the body's, in its own frame, kg·m²
    // The keys store angles in `convention` (a track in Euler rotation mode): the Euler channels then start from
    // the stored angles of the key at or before the first sample, so that they are the angles the track
    // interpolates (a 720° spin is a ramp to 720°) and each key sits at its stored angles.
    bool keysStoreAngles = false;
};

struct ChannelCurves {
    // Increasing: the even samples merged with the key times inside the range.
    std::vector<double> times;
    // Per channel, one value per time: Euler angles in degrees, quaternion components, angular
    // velocity in rad/s, position in scene units, angular momentum in kg·m²/s, energy in joules.
    std::array<std::vector<double>, kChannelCount> values;
    // Per key inside the range, its index in `times`, and the key's own index in the track.
    std::vector<std::pair<std::size_t, std::size_t>> keySamples;
    // The key's stored quaternion components (w, x, y, z) of every key in keySamples, in its order:
    // what the quaternion channels draw as keys. A key stored with the sign opposite to the curve's
    // shows off the curve, until the Euler filter flips it (apply_euler_filter_command.h).
    std::vector<std::array<double, 4>> keyQuaternions;
    // Spans [from, to] in seconds where the middle angle is within kGimbalZoneRadians of lock.
    std::vector<std::pair<double, double>> gimbalZones;

    double value(Channel channel, std::size_t sample) const { return values[static_cast<std::size_t>(channel)][sample]; }
};

// The channels of `motion`, whose keys are `keys`. Throws std::invalid_argument for fewer than two
// samples or an end not after the start.
ChannelCurves sampleChannels(const TrackMotion& motion, const std::vector<Keyframe>& keys, const ChannelSettings& settings);

} // namespace gyre::model
