#include "io/baked_scene.h"

#include "model/input_error.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <ranges>

namespace gyre::io {

namespace {

// A sample's time as glTF readers read it: float32 seconds, which Assimp's reader (Gyre's own import)
// multiplies by 1000 in float32 to get milliseconds. That product's step is up to 1.024 times the
// seconds' step, so two float32 seconds one step apart can become the same millisecond. Samples with
// the same seconds have the same milliseconds, and rounding is monotonic, so once no two samples share
// their milliseconds, both the seconds and the milliseconds increase strictly.
float readTime(const model::TimedPose& sample)
{
    return static_cast<float>(static_cast<float>(sample.time) * 1000.0f);
}

// One sample per time as read back (readTime, prepareGltfTimes); `keyTimes` increasing, shifted as the samples are.
std::vector<model::TimedPose> mergedSamples(const std::vector<model::TimedPose>& samples,
                                            const std::vector<double>& keyTimes)
{
    const auto atKey = [&keyTimes](const model::TimedPose& sample) {
        return std::ranges::binary_search(keyTimes, sample.time);
    };
    std::vector<model::TimedPose> result;
    result.reserve(samples.size());
    for (auto run = samples.begin(); run != samples.end();) {
        const auto runEnd = std::find_if(run, samples.end(), [time = readTime(*run)](const model::TimedPose& s) {
            return readTime(s) != time;
        });
        const std::ranges::subrange backwards(std::make_reverse_iterator(runEnd), std::make_reverse_iterator(run));
        const auto lastKey = std::ranges::find_if(backwards, atKey);
        result.push_back(lastKey != backwards.end() ? *lastKey : *std::prev(runEnd));
        run = runEnd;
    }
    return result;
}

template <class Key>
bool hasDistinctReadTimes(const std::vector<Key>& points)
{
    return std::ranges::adjacent_find(points, [](const Key& a, const Key& b) {
               return readTime({a.time, {}}) == readTime({b.time, {}});
           }) == points.end();
}

// The factor s with a = s·b when the quaternions are parallel, to 1e-9 of a's length (the same rotation,
// s < 0 on the other hemisphere), else none.
std::optional<double> parallelFactor(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    const double factor = a.coeffs().dot(b.coeffs()) / b.coeffs().squaredNorm();
    if (!((a.coeffs() - factor * b.coeffs()).norm() <= 1e-9 * a.coeffs().norm()))
        return std::nullopt;
    return factor;
}

// A piece of the spline a track plays: `spline`'s raw cubic times `factor`, over [from, to].
struct SplinePiece {
    const HermiteQuaternionSpline* spline = nullptr;
    double from = 0.0;
    double to = 0.0;
    double factor = 1.0;
    HermiteQuaternionSpline::RawSample raw(double time) const
    {
        HermiteQuaternionSpline::RawSample sample = spline->raw(time);
        sample.value.coeffs() *= factor;
        sample.derivative.coeffs() *= factor;
        return sample;
    }
};

} // namespace

std::vector<SplineKey> rotationSplineOf(const model::MotionTrack& track, const std::vector<double>& times)
{
    if (track.interpolation != InterpolationMethod::Hermite || track.keys.size() < 2)
        return {};
    std::vector<OrientationKey> keys;
    for (const model::Keyframe& key : track.keys)
        keys.push_back({key.time, key.pose.orientation});
    const HermiteQuaternionSpline throughKeys = HermiteQuaternionSpline::throughKeys(std::move(keys));
    const double first = track.keys.front().time;
    const double last = track.keys.back().time;
    std::vector<SplinePiece> pieces;
    std::optional<HermiteQuaternionSpline> fitted;
    if (track.sketch.fittedCurve.empty()) {
        pieces.push_back({&throughKeys, first, last, 1.0});
    } else {
        fitted.emplace(track.sketch.fittedCurve);
        const double fitStart = fitted->startTime();
        const double fitEnd = fitted->endTime();
        if (fitStart < first || fitEnd > last)
            return {};
        // The keys' spline on one side of the fit, scaled to meet the fit's raw value where they join.
        const auto addOutside = [&](double from, double to, double join) {
            if (from == to)
                return true;
            const std::optional<double> factor = parallelFactor(fitted->raw(join).value, throughKeys.raw(join).value);
            if (factor)
                pieces.push_back({&throughKeys, from, to, *factor});
            return factor.has_value();
        };
        if (!addOutside(first, fitStart, fitStart))
            return {};
        pieces.push_back({&*fitted, fitStart, fitEnd, 1.0});
        if (!addOutside(fitEnd, last, fitEnd))
            return {};
    }

    std::vector<double> cuts = times;
    for (const SplinePiece& piece : pieces)
        cuts.insert(cuts.end(), {piece.from, piece.to});
    std::ranges::sort(cuts);
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

    const auto pieceWhere = [&pieces](auto contains) -> const SplinePiece* {
        const auto found = std::ranges::find_if(pieces, contains);
        return found != pieces.end() ? &*found : nullptr;
    };
    std::vector<SplineKey> result;
    result.reserve(cuts.size());
    for (const double time : cuts) {
        const SplinePiece* before = pieceWhere([time](const SplinePiece& p) { return p.from < time && time <= p.to; });
        const SplinePiece* after = pieceWhere([time](const SplinePiece& p) { return p.from <= time && time < p.to; });
        // The fit plays on its closed span (model::TrackMotion::at), so at its ends the value is the fit's;
        // before the first key and after the last the end pieces hold their end values.
        const bool inFit = fitted && time >= fitted->startTime() && time <= fitted->endTime();
        const SplinePiece* played = inFit ? pieceWhere([&](const SplinePiece& p) { return p.spline == &*fitted; })
                                    : after != nullptr  ? after
                                    : before != nullptr ? before
                                    : time < first      ? &pieces.front()
                                                        : &pieces.back();
        const Eigen::Quaterniond held(0.0, 0.0, 0.0, 0.0);
        result.push_back({time, played->raw(time).value, before != nullptr ? before->raw(time).derivative : held,
                          after != nullptr ? after->raw(time).derivative : held});
    }
    return result;
}

std::vector<PositionSplineKey> positionSplineOf(const model::MotionTrack& track, const std::vector<double>& times)
{
    const std::optional<PositionCurve> curve = model::cubicPositionCurve(track);
    if (!curve)
        return {};
    const double first = track.keys.front().time;
    const double last = track.keys.back().time;
    std::vector<PositionSplineKey> result;
    for (const double time : times) {
        // Held outside the keys: no slope on that side.
        const Eigen::Vector3d velocity = curve->velocity(time);
        result.push_back({time, curve->at(time), time > first ? velocity : Eigen::Vector3d::Zero(),
                          time < last ? velocity : Eigen::Vector3d::Zero()});
    }
    return result;
}

std::vector<std::vector<JointInfluence>> jointInfluences(const model::Skin& skin)
{
    std::vector<std::vector<JointInfluence>> result(skin.joints.size());
    for (std::size_t v = 0; v < skin.vertexJoints.size(); ++v)
        for (std::size_t k = 0; k < 4; ++k)
            if (const float weight = skin.vertexWeights[v][static_cast<Eigen::Index>(k)]; weight > 0.0F)
                result[skin.vertexJoints[v][k]].push_back({static_cast<std::uint32_t>(v), weight});
    return result;
}

QStringList prepareGltfTimes(BakedScene& baked, const model::Scene& scene)
{
    QStringList warnings;
    // Added to every time, samples and keys alike, so that a sample at a key time stays equal to it.
    const double shift = std::max(0.0, -baked.range.start);
    if (shift > 0.0) {
        baked.range.start += shift;
        baked.range.end += shift;
        warnings << FileError::tr("glTF times cannot be negative: the motion is written %1 s later, from 0 s")
                        .arg(FileError::number(shift));
    }
    for (std::size_t i = 0; i < baked.objects.size(); ++i) {
        BakedObject& object = baked.objects[i];
        if (object.samples.empty())
            continue;
        std::vector<double> keyTimes = model::keyTimes(scene.objects.at(i).track);
        for (double& time : keyTimes)
            time += shift;
        for (model::TimedPose& sample : object.samples)
            sample.time += shift;
        for (SplineKey& key : object.rotationSpline)
            key.time += shift;
        for (PositionSplineKey& key : object.positionSpline)
            key.time += shift;
        if (!hasDistinctReadTimes(object.rotationSpline) || !hasDistinctReadTimes(object.positionSpline)) {
            object.rotationSpline.clear();
            object.positionSpline.clear();
            warnings << FileError::tr("'%1': two of its keys are within a float32 step; its rotation and translation "
                                      "are written as baked samples, not as its splines")
                            .arg(QString::fromStdString(object.name));
        }
        const std::size_t before = object.samples.size();
        object.samples = mergedSamples(object.samples, keyTimes);
        if (object.samples.size() < before)
            warnings << FileError::tr("'%1': %2 baked samples are left out, each within a float32 step of the one "
                                      "kept (glTF stores times as float32)")
                            .arg(QString::fromStdString(object.name))
                            .arg(before - object.samples.size());
    }
    return warnings;
}

} // namespace gyre::io
