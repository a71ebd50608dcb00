#include "jobs/fit_input.h"

#include <algorithm>

namespace gyre::jobs {

namespace {

bool sameQuaternion(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.coeffs() == b.coeffs();
}

bool sameKeyInput(const model::Keyframe& a, const model::Keyframe& b)
{
    return a.time == b.time && a.constrained == b.constrained && a.pose.position == b.pose.position
           && (!a.constrained || sameQuaternion(a.pose.orientation, b.pose.orientation));
}

bool sameStroke(const model::DirectionStroke& a, const model::DirectionStroke& b)
{
    return a.points == b.points && a.times == b.times;
}

bool sameMagnitudePoint(const model::MagnitudePoint& a, const model::MagnitudePoint& b)
{
    return a.time == b.time && a.magnitude == b.magnitude;
}

// Everything of the sketch but fittedCurve.
bool sameSketchInput(const model::SketchState& a, const model::SketchState& b)
{
    return std::ranges::equal(a.directionStrokes, b.directionStrokes, sameStroke)
           && std::ranges::equal(a.magnitude, b.magnitude, sameMagnitudePoint) && a.pattern == b.pattern
           && a.patternRepeat == b.patternRepeat && a.window == b.window && a.alpha == b.alpha && a.beta == b.beta
           && a.delta == b.delta;
}

} // namespace

bool sameFitInput(const model::MotionTrack& fitted, const model::MotionTrack& current)
{
    return fitted.interpolation == current.interpolation
           && std::ranges::equal(fitted.keys, current.keys, sameKeyInput)
           && sameSketchInput(fitted.sketch, current.sketch);
}

} // namespace gyre::jobs
