#include "model/value_checks.h"

#include "model/input_error.h"

#include <QLocale>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace gyre::model {

namespace {

// How far from 1 the computed length of a unit vector may be through rounding alone.
constexpr double kRoundingTolerance = 4 * std::numeric_limits<double>::epsilon();

[[noreturn]] void refuse(const QString& message) { throw std::invalid_argument(message.toStdString()); }

// A count as the budget messages write it, with thousands separated: "65,536,000".
QString count(double value) { return QLocale(QLocale::English).toString(value, 'f', 0); }

template <class Vector>
Vector finiteCoefficients(const Vector& value)
{
    if (!value.allFinite())
        refuse(FileError::tr("not all components are finite"));
    return value;
}

// `value` scaled to length 1, if its length is within kUnitLengthTolerance of 1.
template <class Vector>
Vector normalisedNearUnit(const Vector& value, const char* what)
{
    const double length = finiteCoefficients(value).norm();
    if (length == 0.0)
        refuse(FileError::tr("the %1 is zero").arg(FileError::tr(what)));
    if (!(std::abs(length - 1.0) <= kUnitLengthTolerance))
        refuse(FileError::tr("the %1 has length %2; it must have length 1").arg(FileError::tr(what), FileError::number(length)));
    // Unit up to rounding: left as it is, so that a value read back is the value written.
    if (std::abs(length - 1.0) <= kRoundingTolerance)
        return value;
    return value / length;
}

// Times that are finite and strictly increase; `timeOf` gives an item's time.
template <class Item, class TimeOf>
void checkIncreasingTimes(const std::vector<Item>& items, TimeOf timeOf)
{
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i == 0)
            timeValue(std::invoke(timeOf, items[i]));
        else
            timeAfter(std::invoke(timeOf, items[i]), std::invoke(timeOf, items[i - 1]));
    }
}

} // namespace

double finiteNumber(double value)
{
    if (!std::isfinite(value))
        refuse(FileError::tr("%1 is not a finite number").arg(FileError::number(value)));
    return value;
}

double nonNegativeNumber(double value)
{
    if (!(finiteNumber(value) >= 0.0))
        refuse(FileError::tr("%1 is negative").arg(FileError::number(value)));
    return value;
}

double positiveNumber(double value)
{
    if (!(finiteNumber(value) > 0.0))
        refuse(FileError::tr("%1 is not positive").arg(FileError::number(value)));
    return value;
}

Eigen::Vector3d finiteVector(const Eigen::Vector3d& value) { return finiteCoefficients(value); }
Eigen::Vector2d finiteVector(const Eigen::Vector2d& value) { return finiteCoefficients(value); }
Eigen::Vector3d unitVector(const Eigen::Vector3d& value) { return normalisedNearUnit(value, QT_TRANSLATE_NOOP("gyre::FileError", "direction")); }

Eigen::Quaterniond unitQuaternion(const Eigen::Quaterniond& value)
{
    return Eigen::Quaterniond(normalisedNearUnit(Eigen::Vector4d(value.coeffs()), QT_TRANSLATE_NOOP("gyre::FileError", "quaternion")));
}

Eigen::Quaterniond finiteQuaternion(const Eigen::Quaterniond& value)
{
    return Eigen::Quaterniond(finiteCoefficients(Eigen::Vector4d(value.coeffs())));
}

Eigen::Vector3d positionValue(const Eigen::Vector3d& position)
{
    if (!(finiteVector(position).cwiseAbs().maxCoeff() <= kMaxPositionCoordinate))
        refuse(gyre::FileError::tr("position coordinate %1 is beyond ±%2")
                   .arg(FileError::number(position.cwiseAbs().maxCoeff()), FileError::number(kMaxPositionCoordinate)));
    return position;
}

double timeValue(double time)
{
    if (!(std::abs(finiteNumber(time)) <= kMaxTimeSeconds))
        refuse(FileError::tr("time %1 is beyond ±%2 s").arg(FileError::number(time), FileError::number(kMaxTimeSeconds)));
    return time;
}

double timeAfter(double time, double previous)
{
    if (!(timeValue(time) > previous))
        refuse(FileError::tr("time %1 does not come after the time before it, %2").arg(FileError::number(time), FileError::number(previous)));
    return time;
}

Eigen::Quaterniond controlValue(const Eigen::Quaterniond& value)
{
    // stableNorm: a denormal or a huge component would under- or overflow the squares of norm().
    const double length = Eigen::Vector4d(finiteQuaternion(value).coeffs()).stableNorm();
    if (!(length >= kMinControlValueNorm))
        refuse(gyre::FileError::tr("the value has length %1; a fitted value needs length at least %2")
                   .arg(FileError::number(length), FileError::number(kMinControlValueNorm)));
    return value;
}

Eigen::Quaterniond controlDerivative(const Eigen::Quaterniond& derivative)
{
    const double length = Eigen::Vector4d(finiteQuaternion(derivative).coeffs()).stableNorm();
    if (!(length <= kMaxControlDerivativeNorm))
        refuse(gyre::FileError::tr("the derivative has length %1 per second; the most it may have is %2")
                   .arg(FileError::number(length), FileError::number(kMaxControlDerivativeNorm)));
    return derivative;
}

void checkKeyframe(Keyframe& key)
{
    timeValue(key.time);
    key.pose.orientation = unitQuaternion(key.pose.orientation);
    positionValue(key.pose.position);
}

void checkKeyframes(std::vector<Keyframe>& keys)
{
    for (Keyframe& key : keys)
        checkKeyframe(key);
    checkIncreasingTimes(keys, &Keyframe::time);
}

void checkStroke(DirectionStroke& stroke)
{
    if (stroke.points.empty())
        refuse(FileError::tr("a stroke needs at least one point"));
    for (Eigen::Vector3d& point : stroke.points)
        point = unitVector(point);
    if (!stroke.times.empty() && stroke.times.size() != stroke.points.size())
        refuse(FileError::tr("a stroke has no times or one per point"));
    checkIncreasingTimes(stroke.times, std::identity{});
}

void checkMagnitudeCurve(const std::vector<MagnitudePoint>& points)
{
    for (const MagnitudePoint& point : points)
        nonNegativeNumber(point.magnitude);
    checkIncreasingTimes(points, &MagnitudePoint::time);
}

void checkPattern(const std::vector<Eigen::Vector2d>& pattern, int repeat)
{
    for (const Eigen::Vector2d& point : pattern)
        finiteVector(point);
    if (repeat < 0)
        refuse(FileError::tr("the pattern's repeat count %1 is negative").arg(repeat));
}

void checkWindow(const std::optional<std::pair<double, double>>& window)
{
    if (window)
        timeAfter(window->second, timeValue(window->first));
}

void checkFittedCurve(const std::vector<HermiteControlPoint>& curve)
{
    for (const HermiteControlPoint& point : curve) {
        controlValue(point.value);
        controlDerivative(point.derivative);
    }
    checkIncreasingTimes(curve, &HermiteControlPoint::time);
}

void checkSketch(SketchState& sketch)
{
    for (DirectionStroke& stroke : sketch.directionStrokes)
        checkStroke(stroke);
    checkMagnitudeCurve(sketch.magnitude);
    checkPattern(sketch.pattern, sketch.patternRepeat);
    checkWindow(sketch.window);
    nonNegativeNumber(sketch.alpha);
    nonNegativeNumber(sketch.beta);
    positiveNumber(sketch.delta);
    checkFittedCurve(sketch.fittedCurve);
    checkKeyframes(sketch.keysBeforeFit);
    if (sketch.fittedCurve.empty() && !sketch.keysBeforeFit.empty())
        refuse(FileError::tr("keys to restore without an applied fit"));
}

void checkSubdivision(const SubdivisionSettings& settings)
{
    if (settings.levels < 0 || settings.levels > kMaxSubdivisionLevels)
        refuse(FileError::tr("subdivision levels %1 are outside 0 to %2").arg(settings.levels).arg(kMaxSubdivisionLevels));
}

void checkPoseBudget(std::size_t keyCount, InterpolationMethod interpolation, const SubdivisionSettings& settings)
{
    if (interpolation == InterpolationMethod::Ballistic && keyCount > kMaxBallisticKeys)
        refuse(FileError::tr("%1 keys on a ballistic track, which solves a free flight for each span; it may hold %2")
                   .arg(count(static_cast<double>(keyCount)), count(static_cast<double>(kMaxBallisticKeys))));
    if (interpolation != InterpolationMethod::Screw)
        return;
    checkSubdivision(settings);
    // n·2^L, at least the cyclic and the open count; exact in a double for L ≤ kMaxSubdivisionLevels.
    const double poses = std::ldexp(static_cast<double>(keyCount), settings.levels);
    if (poses > static_cast<double>(kMaxSubdividedPoses))
        refuse(FileError::tr("%1 keys at %2 levels make %3 poses; the budget is %4")
                   .arg(count(static_cast<double>(keyCount)))
                   .arg(settings.levels)
                   .arg(count(poses), count(static_cast<double>(kMaxSubdividedPoses))));
}

void checkTrack(MotionTrack& track)
{
    checkKeyframes(track.keys.edit());
    checkSubdivision(track.subdivision);
    checkPoseBudget(track.keys.size(), track.interpolation, track.subdivision);
    checkSketch(track.sketch);
}

double frameRate(double fps)
{
    if (!(positiveNumber(fps) <= kMaxFps))
        refuse(FileError::tr("a frame rate of %1 is above %2").arg(FileError::number(fps), FileError::number(kMaxFps)));
    return fps;
}

void checkTimeRange(double fps, double startTime, double endTime)
{
    frameRate(fps);
    if (!(timeValue(endTime) > timeValue(startTime)))
        refuse(FileError::tr("the end time %1 does not come after the start time %2")
                   .arg(FileError::number(endTime), FileError::number(startTime)));
    // Both times are within ±kMaxTimeSeconds and fps ≤ kMaxFps, so the product is finite.
    const double frames = (endTime - startTime) * fps;
    if (frames > kMaxFrames)
        refuse(FileError::tr("%1 s at %2 fps make %3 frames; the budget is %4")
                   .arg(FileError::number(endTime - startTime), FileError::number(fps), count(std::ceil(frames)),
                        count(kMaxFrames)));
}

void checkMesh(const Mesh& mesh)
{
    for (const Eigen::Vector3f& position : mesh.positions)
        if (!position.allFinite())
            refuse(FileError::tr("a mesh position is not finite"));
    for (const Eigen::Vector3f& normal : mesh.normals)
        if (!normal.allFinite())
            refuse(FileError::tr("a mesh normal is not finite"));
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
        refuse(FileError::tr("the mesh has %1 normals for %2 positions").arg(mesh.normals.size()).arg(mesh.positions.size()));
    if (mesh.indices.size() % 3 != 0)
        refuse(FileError::tr("the mesh's %1 indices do not make whole triangles").arg(mesh.indices.size()));
    for (std::uint32_t index : mesh.indices)
        if (index >= mesh.positions.size())
            refuse(FileError::tr("mesh index %1 is beyond its %2 positions").arg(index).arg(mesh.positions.size()));
    if (!mesh.skin.empty())
        checkSkin(mesh.skin, mesh.positions.size());
}

void checkSkin(const Skin& skin, std::size_t positions)
{
    const std::size_t joints = skin.joints.size();
    if (joints > kMaxSkinJoints)
        refuse(FileError::tr("the skin has %1 joints, more than the %2 a mesh may follow").arg(joints).arg(kMaxSkinJoints));
    for (std::size_t j = 0; j < joints; ++j)
        if (skin.joints[j] == kNoObject || std::count(skin.joints.begin(), skin.joints.begin() + j, skin.joints[j]) > 0)
            refuse(FileError::tr("skin joint %1 is 0 or named twice").arg(j));
    if (skin.inverseBinds.size() != joints)
        refuse(FileError::tr("the skin has %1 inverse bind matrices for %2 joints").arg(skin.inverseBinds.size()).arg(joints));
    for (std::size_t j = 0; j < joints; ++j) {
        const Eigen::Matrix4f& matrix = skin.inverseBinds[j];
        if (!matrix.allFinite() || matrix.row(3) != Eigen::RowVector4f(0, 0, 0, 1))
            refuse(FileError::tr("the inverse bind matrix of skin joint %1 is not a finite affine transform").arg(j));
    }
    if (skin.vertexJoints.size() != positions || skin.vertexWeights.size() != positions)
        refuse(FileError::tr("the skin has %1 joint sets and %2 weight sets for %3 positions")
                   .arg(skin.vertexJoints.size())
                   .arg(skin.vertexWeights.size())
                   .arg(positions));
    for (std::size_t v = 0; v < positions; ++v) {
        for (const std::uint16_t joint : skin.vertexJoints[v])
            if (joint >= joints)
                refuse(FileError::tr("skin vertex %1 names joint %2 of %3").arg(v).arg(joint).arg(joints));
        const Eigen::Vector4f& weights = skin.vertexWeights[v];
        if (!weights.allFinite() || (weights.array() < 0.0F).any() || weights.sum() > 1.0F + kSkinWeightTolerance)
            refuse(FileError::tr("the weights of skin vertex %1 are not finite, ≥ 0 and at most 1 in sum").arg(v));
    }
}

} // namespace gyre::model
