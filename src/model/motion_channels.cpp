#include "model/motion_channels.h"

#include "core/quaternion_math.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace gyre::model {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

std::vector<double>& channel(ChannelCurves& curves, Channel which)
{
    return curves.values[static_cast<std::size_t>(which)];
}

// The spans of `times` where `inZone` holds, each from its first sample to its last.
std::vector<std::pair<double, double>> zonesOf(const std::vector<double>& times, const std::vector<bool>& inZone)
{
    std::vector<std::pair<double, double>> zones;
    for (std::size_t i = 0; i < times.size(); ++i) {
        if (!inZone[i])
            continue;
        if (i > 0 && inZone[i - 1])
            zones.back().second = times[i];
        else
            zones.emplace_back(times[i], times[i]);
    }
    return zones;
}

} // namespace

ChannelCurves sampleChannels(const TrackMotion& motion, const std::vector<Keyframe>& keys, const ChannelSettings& settings)
{
    if (settings.samples < 2 || !(settings.end > settings.start))
        throw std::invalid_argument("the channels need two samples or more over a range whose end is after its start");
    ChannelCurves curves;
    std::vector<double> keyTimes;
    keyTimes.reserve(keys.size());
    for (const Keyframe& key : keys)
        keyTimes.push_back(key.time);
    // Evenly spaced samples, the keys' times among them, so that every key sits on its curves.
    const double fps = static_cast<double>(settings.samples - 1) / (settings.end - settings.start);
    curves.times = bakeTimes(keyTimes, {settings.start, settings.end, fps});
    const std::size_t count = curves.times.size();
    for (std::vector<double>& values : curves.values)
        values.reserve(count);

    std::vector<Eigen::Quaterniond> rotations;
    rotations.reserve(count);
    // The quaternion's sign follows on from the first key's as stored, sample by sample.
    Eigen::Quaterniond previous = keys.empty() ? Eigen::Quaterniond::Identity() : keys.front().pose.orientation;
    for (const double time : curves.times) {
        const Pose pose = motion.at(time);
        const Eigen::Quaterniond q = alignedWith(pose.orientation, previous);
        previous = q;
        rotations.push_back(q);
        const Eigen::Vector3d worldVelocity = motion.angularVelocity(time);
        const Eigen::Vector3d localVelocity = q.conjugate() * worldVelocity;
        const bool world = settings.velocityFrame == VelocityFrame::World;
        const Eigen::Vector3d velocity = world ? worldVelocity : localVelocity;
        const std::array quaternion{q.w(), q.x(), q.y(), q.z()};
        for (std::size_t c = 0; c < 4; ++c)
            curves.values[static_cast<std::size_t>(Channel::QuaternionW) + c].push_back(quaternion[c]);
        for (int c = 0; c < 3; ++c) {
            curves.values[static_cast<std::size_t>(Channel::AngularVelocityX) + static_cast<std::size_t>(c)].push_back(velocity[c]);
            curves.values[static_cast<std::size_t>(Channel::PositionX) + static_cast<std::size_t>(c)].push_back(pose.position[c]);
        }
        channel(curves, Channel::AngularSpeed).push_back(worldVelocity.norm());
        // In the object's frame L = I·ω_local; turned into the parent's, R·I·Rᵀ·ω.
        const Eigen::Vector3d localMomentum = settings.inertia * localVelocity;
        const Eigen::Vector3d momentum = world ? Eigen::Vector3d(q * localMomentum) : localMomentum;
        for (int c = 0; c < 3; ++c)
            curves.values[static_cast<std::size_t>(Channel::AngularMomentumX) + static_cast<std::size_t>(c)].push_back(momentum[c]);
        channel(curves, Channel::AngularMomentumMagnitude).push_back(localMomentum.norm());
        channel(curves, Channel::KineticEnergy).push_back(0.5 * localVelocity.dot(localMomentum));
    }

    std::optional<Eigen::Vector3d> startAngles;
    if (settings.keysStoreAngles && !keys.empty()) {
        const auto after = std::upper_bound(keys.begin(), keys.end(), curves.times.front(),
                                            [](double time, const Keyframe& key) { return time < key.time; });
        startAngles = (after == keys.begin() ? keys.front() : *(after - 1)).eulerAngles;
    }
    const std::vector<Eigen::Vector3d> angles = unwrappedEulerAngles(rotations, settings.convention, startAngles);
    std::vector<bool> nearLock(count);
    for (std::size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c)
            curves.values[static_cast<std::size_t>(c)].push_back(angles[i][c] * kDegreesPerRadian);
        nearLock[i] = eulerAnglesFromQuaternion(rotations[i], settings.convention).gimbalLockDistance < kGimbalZoneRadians;
    }
    curves.gimbalZones = zonesOf(curves.times, nearLock);

    for (std::size_t k = 0; k < keys.size(); ++k) {
        const double time = keys[k].time;
        if (time < settings.start || time > settings.end)
            continue;
        const auto at = std::lower_bound(curves.times.begin(), curves.times.end(), time);
        curves.keySamples.emplace_back(static_cast<std::size_t>(at - curves.times.begin()), k);
        const Eigen::Quaterniond& stored = keys[k].pose.orientation;
        curves.keyQuaternions.push_back({stored.w(), stored.x(), stored.y(), stored.z()});
    }
    return curves;
}

} // namespace gyre::model
