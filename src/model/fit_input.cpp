#include "model/fit_input.h"

#include <algorithm>

namespace gyre::model {

namespace {

bool sameQuaternion(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.coeffs() == b.coeffs();
}

bool sameKey(const Keyframe& a, const Keyframe& b)
{
    return a.time == b.time && a.constrained == b.constrained && a.pose.position == b.pose.position
           && sameQuaternion(a.pose.orientation, b.pose.orientation);
}

bool sameKeys(const std::vector<Keyframe>& a, const std::vector<Keyframe>& b)
{
    return std::ranges::equal(a, b, sameKey);
}

bool sameStroke(const DirectionStroke& a, const DirectionStroke& b)
{
    return a.points == b.points && a.times == b.times;
}

bool sameMagnitudePoint(const MagnitudePoint& a, const MagnitudePoint& b)
{
    return a.time == b.time && a.magnitude == b.magnitude;
}

// Everything of the sketch the fit reads: all but the applied fit and the keys it moved.
bool sameSketchInput(const SketchState& a, const SketchState& b)
{
    return std::ranges::equal(a.directionStrokes, b.directionStrokes, sameStroke)
           && std::ranges::equal(a.magnitude, b.magnitude, sameMagnitudePoint) && a.pattern == b.pattern
           && a.patternRepeat == b.patternRepeat && a.window == b.window && a.alpha == b.alpha && a.beta == b.beta
           && a.delta == b.delta;
}

} // namespace

MotionTrack withoutFit(MotionTrack track)
{
    for (const Keyframe& before : track.sketch.keysBeforeFit) {
        std::vector<Keyframe>& keys = track.keys.edit();
        const auto key = std::ranges::find(keys, before.time, &Keyframe::time);
        if (key != keys.end())
            key->pose = before.pose;
    }
    track.sketch.keysBeforeFit.clear();
    track.sketch.fittedCurve.clear();
    return track;
}

bool sameFitInput(const MotionTrack& fitted, const MotionTrack& current)
{
    const MotionTrack a = withoutFit(fitted);
    const MotionTrack b = withoutFit(current);
    const bool screw = a.interpolation == InterpolationMethod::Screw;
    return a.interpolation == b.interpolation && (!screw || a.subdivision == b.subdivision)
           && sameKeys(a.keys, b.keys) && sameSketchInput(a.sketch, b.sketch);
}

bool fitResultApplies(const MotionTrack& fitted, const MotionTrack& current, const FitResult& applied)
{
    return sameFitInput(fitted, current)
           && (sameKeys(current.keys, fitted.keys) || sameKeys(current.keys, applied.keys));
}

} // namespace gyre::model
