#include "model/fit_input.h"

#include <algorithm>

namespace gyre::model {

namespace {

bool sameQuaternion(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.coeffs() == b.coeffs();
}

bool sameKeyInput(const Keyframe& a, const Keyframe& b)
{
    return a.time == b.time && a.constrained == b.constrained && a.pose.position == b.pose.position
           && (!a.constrained || sameQuaternion(a.pose.orientation, b.pose.orientation));
}

bool sameStroke(const DirectionStroke& a, const DirectionStroke& b)
{
    return a.points == b.points && a.times == b.times;
}

bool sameMagnitudePoint(const MagnitudePoint& a, const MagnitudePoint& b)
{
    return a.time == b.time && a.magnitude == b.magnitude;
}

// Everything of the sketch but fittedCurve.
bool sameSketchInput(const SketchState& a, const SketchState& b)
{
    return std::ranges::equal(a.directionStrokes, b.directionStrokes, sameStroke)
           && std::ranges::equal(a.magnitude, b.magnitude, sameMagnitudePoint) && a.pattern == b.pattern
           && a.patternRepeat == b.patternRepeat && a.window == b.window && a.alpha == b.alpha && a.beta == b.beta
           && a.delta == b.delta;
}

} // namespace

bool sameFitInput(const MotionTrack& fitted, const MotionTrack& current)
{
    return fitted.interpolation == current.interpolation
           && std::ranges::equal(fitted.keys, current.keys, sameKeyInput)
           && sameSketchInput(fitted.sketch, current.sketch);
}

} // namespace gyre::model
