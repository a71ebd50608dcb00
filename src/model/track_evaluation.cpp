#include "model/track_evaluation.h"

#include "core/key_time_map.h"
#include "fit/ballistic_flight.h"
#include "core/polyscrew.h"
#include "core/position_curve.h"
#include "core/quaternion_math.h"
#include "core/subdivision.h"
#include "core/number_text.h"
#include "model/object_mass.h"
#include "model/value_checks.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace gyre::model {

namespace detail {

// The motion through a track's keys, without its fit.
class KeyedMotion {
public:
    virtual ~KeyedMotion() = default;
    virtual Pose at(double time) const = 0;

protected:
    KeyedMotion() = default;
    KeyedMotion(const KeyedMotion&) = default;
    KeyedMotion& operator=(const KeyedMotion&) = default;
};

} // namespace detail

namespace {

bool hasCubicPositions(InterpolationMethod method)
{
    return method == InterpolationMethod::Squad || method == InterpolationMethod::Hermite;
}

std::vector<PositionKey> positionKeys(const MotionTrack& track)
{
    std::vector<PositionKey> keys;
    keys.reserve(track.keys.size());
    for (const Keyframe& key : track.keys)
        keys.push_back({key.time, key.pose.position});
    return keys;
}

// An orientation curve with positions to go with it.
class CurveMotion final : public detail::KeyedMotion {
public:
    CurveMotion(const MotionTrack& track, const EulerConvention& eulerConvention)
        : orientations_(makeOrientationCurve(track.interpolation, orientationKeys(track), eulerConvention))
        , positions_(positionKeys(track), hasCubicPositions(track.interpolation) ? PositionCurve::Shape::Cubic
                                                                                 : PositionCurve::Shape::Linear)
    {
    }

    Pose at(double time) const override { return {orientations_->sample(time).value, positions_.at(time)}; }

private:
    static std::vector<OrientationKey> orientationKeys(const MotionTrack& track)
    {
        std::vector<OrientationKey> keys;
        keys.reserve(track.keys.size());
        for (const Keyframe& key : track.keys)
            keys.push_back({key.time, key.pose.orientation});
        return keys;
    }

    std::unique_ptr<OrientationCurve> orientations_;
    PositionCurve positions_;
};

// The subdivided polyscrew through the key poses, with time mapped to its parameter by the C¹ time
// map of the key times.
class ScrewMotion final : public detail::KeyedMotion {
public:
    explicit ScrewMotion(const MotionTrack& track)
        : timeMap_(keyTimes(track), track.subdivision.cyclic)
        , motion_(subdividePolyscrew(posesOf(track), track.subdivision), track.subdivision.cyclic,
                  std::size_t{1} << track.subdivision.levels)
    {
    }

    Pose at(double time) const override { return motion_.at(timeMap_.parameterAt(time)); }

private:
    static std::vector<Pose> posesOf(const MotionTrack& track)
    {
        std::vector<Pose> poses;
        poses.reserve(track.keys.size());
        for (const Keyframe& key : track.keys)
            poses.push_back(key.pose);
        return poses;
    }

    KeyTimeMap timeMap_;
    Polyscrew motion_;
};

// Every span a free flight of the body (fit/ballistic_flight.h), its solution the track's choice; one key
// is held.
class BallisticMotion final : public detail::KeyedMotion {
public:
    BallisticMotion(const MotionTrack& track, const MassProperties& body)
        : flight_(flightOf(track, body))
        , held_(track.keys.front().pose)
    {
    }

    Pose at(double time) const override { return flight_ ? flight_->at(time) : held_; }

    std::vector<TrackMotion::FlightChoice> choices() const
    {
        std::vector<TrackMotion::FlightChoice> result;
        if (flight_)
            for (const fit::BallisticFlight::Span& span : flight_->spans())
                result.push_back({span.chosen, span.solutions.size()});
        return result;
    }

private:
    static std::optional<fit::BallisticFlight> flightOf(const MotionTrack& track, const MassProperties& body)
    {
        if (track.keys.size() < 2)
            return std::nullopt;
        std::vector<fit::FlightKey> keys;
        keys.reserve(track.keys.size());
        for (const Keyframe& key : track.keys)
            keys.push_back({key.time, key.pose});
        std::vector<std::optional<std::size_t>> choices;
        for (std::size_t i = 0; i + 1 < track.keys.size(); ++i) {
            const int choice = track.keys[i].flightSolution;
            choices.push_back(choice >= 0 ? std::optional<std::size_t>(static_cast<std::size_t>(choice)) : std::nullopt);
        }
        fit::FlightBody flightBody;
        flightBody.inertia = body.inertia;
        flightBody.centreOfMass = body.centre;
        return fit::BallisticFlight(keys, flightBody, choices);
    }

    std::optional<fit::BallisticFlight> flight_;
    Pose held_;
};

std::unique_ptr<const detail::KeyedMotion> keyedMotion(const MotionTrack& track, const EulerConvention& eulerConvention,
                                                       const MassProperties& body)
{
    if (track.keys.empty())
        return nullptr;
    if (track.interpolation == InterpolationMethod::Ballistic)
        return std::make_unique<BallisticMotion>(track, body);
    if (track.interpolation == InterpolationMethod::Screw) {
        if (track.subdivision.levels < 0 || track.subdivision.levels >= 32)
            throw std::invalid_argument("subdivision levels must be between 0 and 31");
        return std::make_unique<ScrewMotion>(track);
    }
    return std::make_unique<CurveMotion>(track, eulerConvention);
}

std::optional<HermiteQuaternionSpline> fittedSpline(const SketchState& sketch)
{
    if (sketch.fittedCurve.empty())
        return std::nullopt;
    return HermiteQuaternionSpline(sketch.fittedCurve);
}

std::optional<std::pair<double, double>> cycleOf(const MotionTrack& track)
{
    if (track.interpolation != InterpolationMethod::Screw || !track.subdivision.cyclic || track.keys.size() < 2)
        return std::nullopt;
    return std::pair(track.keys.front().time, KeyTimeMap(keyTimes(track), true).period());
}

} // namespace

TrackMotion::TrackMotion(const MotionTrack& track, const EulerConvention& eulerConvention, const MassProperties& body)
    : keyed_(keyedMotion(track, eulerConvention, body))
    , fitted_(fittedSpline(track.sketch))
    , cycle_(cycleOf(track))
{
    if (const auto* ballistic = dynamic_cast<const BallisticMotion*>(keyed_.get()))
        flightChoices_ = ballistic->choices();
}

TrackMotion::~TrackMotion() = default;
TrackMotion::TrackMotion(TrackMotion&&) noexcept = default;
TrackMotion& TrackMotion::operator=(TrackMotion&&) noexcept = default;

Pose TrackMotion::at(double time) const
{
    Pose pose = keyed_ ? keyed_->at(time) : Pose{};
    if (!fitted_)
        return pose;
    double played = time;
    if (cycle_ && (time < cycle_->first || time >= cycle_->first + cycle_->second)) {
        const auto [start, period] = *cycle_;
        played = start + std::fmod(time - start, period);
        if (played < start)
            played += period;
    }
    if (played >= fitted_->startTime() && played <= fitted_->endTime())
        pose.orientation = fitted_->sample(played).value;
    return pose;
}

Eigen::Vector3d TrackMotion::angularVelocity(double time) const
{
    const Eigen::Quaterniond before = at(time - kAngularVelocityStep).orientation;
    const Eigen::Quaterniond after = at(time + kAngularVelocityStep).orientation;
    // The rotation vector 2·log(q(t+h)·q(t−h)⁻¹), turned in 2h.
    return quatLog(after * before.conjugate()) / kAngularVelocityStep;
}

Pose unitSample(const Pose& pose, double time)
{
    const double length = pose.orientation.norm();
    if (!(std::abs(length - 1.0) <= kBakedUnitTolerance && pose.position.allFinite()))
        throw std::invalid_argument("the pose at " + formatNumber(time) + " s is not a finite pose with a unit "
                                    "orientation (its quaternion has length " + formatNumber(length) + ")");
    return pose;
}

double bakeSampleBound(const BakeRange& range, std::size_t keyCount)
{
    // One frame more than the product promises, in case rounding put it just below a whole number.
    return std::floor((range.end - range.start) * range.fps) + 2.0 + static_cast<double>(keyCount);
}

std::vector<double> bakeTimes(const std::vector<double>& keyTimes, const BakeRange& range)
{
    if (!(std::isfinite(range.fps) && range.fps > 0.0))
        throw std::invalid_argument("a bake needs a finite frame rate above zero");
    if (!(std::isfinite(range.start) && std::isfinite(range.end) && range.start <= range.end))
        throw std::invalid_argument("a bake needs a finite range whose start is not after its end");
    const double frames = bakeSampleBound(range, 0);
    // Checked as a double before it becomes a count: a cast of a value beyond the integer range is undefined.
    if (!(frames <= kMaxFrames + 2.0))
        throw std::invalid_argument("a bake of " + formatNumber(range.end - range.start) + " s at " +
                                    formatNumber(range.fps) + " fps makes " + formatNumber(frames) +
                                    " frames; the budget is " + formatNumber(kMaxFrames));
    auto key = std::lower_bound(keyTimes.begin(), keyTimes.end(), range.start);
    const auto keysEnd = std::upper_bound(key, keyTimes.end(), range.end);
    std::vector<double> times;
    times.reserve(static_cast<std::size_t>(frames) + static_cast<std::size_t>(keysEnd - key));
    for (std::size_t k = 0; k < static_cast<std::size_t>(frames); ++k) {
        const double time = range.start + static_cast<double>(k) / range.fps;
        while (key != keysEnd && *key < time - kKeyMergeSeconds)
            times.push_back(*key++);
        const bool atKey = key != keysEnd && std::abs(*key - time) <= kKeyMergeSeconds;
        if (!atKey && time <= range.end)
            times.push_back(time);
    }
    times.insert(times.end(), key, keysEnd);
    return times;
}

MassProperties flightBodyOf(const SceneObject& object)
{
    return object.track.interpolation == InterpolationMethod::Ballistic ? objectMassProperties(object).properties
                                                                        : MassProperties{};
}

std::vector<double> keyTimes(const MotionTrack& track)
{
    std::vector<double> times;
    times.reserve(track.keys.size());
    for (const Keyframe& key : track.keys)
        times.push_back(key.time);
    return times;
}

std::optional<PositionCurve> cubicPositionCurve(const MotionTrack& track)
{
    if (!hasCubicPositions(track.interpolation) || track.keys.size() < 2)
        return std::nullopt;
    return PositionCurve(positionKeys(track), PositionCurve::Shape::Cubic);
}

std::vector<TimedPose> bakeTrack(const MotionTrack& track, const BakeRange& range,
                                 const EulerConvention& eulerConvention, const MassProperties& body)
{
    const TrackMotion motion(track, eulerConvention, body);
    const std::vector<double> times = bakeTimes(keyTimes(track), range);
    std::vector<TimedPose> poses;
    poses.reserve(times.size());
    for (const double time : times)
        poses.push_back({time, unitSample(motion.at(time), time)});
    return poses;
}

} // namespace gyre::model
