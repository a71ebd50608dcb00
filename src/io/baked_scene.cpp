#include "io/baked_scene.h"

#include "model/input_error.h"

#include <algorithm>
#include <iterator>
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

bool hasDistinctReadTimes(const std::vector<HermiteControlPoint>& points)
{
    return std::ranges::adjacent_find(points, [](const HermiteControlPoint& a, const HermiteControlPoint& b) {
               return readTime({a.time, {}}) == readTime({b.time, {}});
           }) == points.end();
}

} // namespace

std::vector<HermiteControlPoint> rotationSplineOf(const model::MotionTrack& track, const std::vector<double>& times)
{
    if (track.interpolation != InterpolationMethod::Hermite || track.keys.size() < 2)
        return {};
    std::vector<HermiteControlPoint> points = track.sketch.fittedCurve;
    if (points.empty()) {
        std::vector<OrientationKey> keys;
        for (const model::Keyframe& key : track.keys)
            keys.push_back({key.time, key.pose.orientation});
        points = HermiteQuaternionSpline::throughKeys(std::move(keys)).controlPoints();
    } else if (points.front().time != track.keys.front().time || points.back().time != track.keys.back().time) {
        return {};
    }
    const HermiteQuaternionSpline spline(points);
    std::vector<HermiteControlPoint> cut;
    for (const double time : times)
        if (time >= points.front().time && time <= points.back().time) {
            const HermiteQuaternionSpline::RawSample raw = spline.raw(time);
            cut.push_back({time, raw.value, raw.derivative});
        }
    return cut;
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
        for (HermiteControlPoint& point : object.rotationSpline)
            point.time += shift;
        if (!hasDistinctReadTimes(object.rotationSpline)) {
            object.rotationSpline.clear();
            warnings << FileError::tr("'%1': two of its keys are within a float32 step; its rotation is written "
                                      "as baked samples, not as its spline")
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
