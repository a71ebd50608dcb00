#include "fit/angular_velocity_target.h"

#include "core/number_text.h"
#include "core/timed_keys.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace gyre::fit {

namespace {

// Directions closer than this (radians) are one point; consecutive directions within it of opposite
// have no single great arc between them.
constexpr double kSameDirection = 1e-12;

template <class Sample>
void requireTimedCurve(const std::vector<Sample>& samples, const char* what)
{
    if (samples.size() < 2)
        throw std::invalid_argument(std::string(what) + " needs at least two samples");
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (!std::isfinite(samples[i].time))
            throw std::invalid_argument(std::string(what) + " sample " + std::to_string(i) + " has a time that is not finite");
        if (i > 0 && !(samples[i].time > samples[i - 1].time))
            throw std::invalid_argument(std::string(what) + " sample " + std::to_string(i) +
                                        ": times must strictly increase");
    }
}

double arcAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The point a fraction u along the great arc from unit a to unit b (θ apart):
// (sin((1 − u)θ)·a + sin(uθ)·b) / sin θ, or a when they coincide.
Eigen::Vector3d alongArc(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double u)
{
    const double angle = arcAngle(a, b);
    if (angle < kSameDirection)
        return a;
    return (std::sin((1.0 - u) * angle) * a + std::sin(u * angle) * b) / std::sin(angle);
}

// A timed direction curve read by arc length s: its points' cumulative arc lengths.
class ArcLengthCurve {
public:
    explicit ArcLengthCurve(const std::vector<TimedVector>& points)
        : points_(points)
    {
        lengths_.push_back(0.0);
        for (std::size_t i = 1; i < points_.size(); ++i) {
            const Eigen::Vector3d& a = points_[i - 1].value;
            const Eigen::Vector3d& b = points_[i].value;
            lengths_.push_back(lengths_.back() + arcAngle(a, b));
            // The great circle through a and b has normal a × b; at any of its points p the direction
            // of travel is normal × p, so the left-hand normal p × (normal × p) is the normal itself.
            const Eigen::Vector3d normal = a.cross(b);
            normals_.push_back(normal.norm() > 0.0 ? normal.normalized() : Eigen::Vector3d::Zero());
        }
        // An arc of no length has no circle: it borrows its neighbour's.
        for (std::size_t i = 1; i < normals_.size(); ++i)
            if (normals_[i].isZero())
                normals_[i] = normals_[i - 1];
        for (std::size_t i = normals_.size(); i-- > 1;)
            if (normals_[i - 1].isZero())
                normals_[i - 1] = normals_[i];
    }

    double length() const { return lengths_.back(); }

    struct Place {
        Eigen::Vector3d point;
        Eigen::Vector3d across;  // unit, tangent to the sphere, to the left of the direction of travel
        double time;
    };

    Place at(double s) const
    {
        s = std::clamp(s, 0.0, length());
        const auto after = std::upper_bound(lengths_.begin(), lengths_.end(), s);
        std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - lengths_.begin() - 1, 0));
        i = std::min(i, points_.size() - 2);
        const double span = lengths_[i + 1] - lengths_[i];
        const double u = span > 0.0 ? (s - lengths_[i]) / span : 0.0;
        const TimedVector& a = points_[i];
        const TimedVector& b = points_[i + 1];
        return {alongArc(a.value, b.value, u), normals_[i], a.time + u * (b.time - a.time)};
    }

private:
    const std::vector<TimedVector>& points_;
    std::vector<double> lengths_;
    std::vector<Eigen::Vector3d> normals_;  // of each arc
};

} // namespace

AngularVelocityTarget AngularVelocityTarget::fromSamples(std::vector<TimedVector> samples)
{
    requireTimedCurve(samples, "the angular velocity");
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (!samples[i].value.allFinite())
            throw std::invalid_argument("angular velocity sample " + std::to_string(i) + " is not finite");
    AngularVelocityTarget target;
    target.start_ = samples.front().time;
    target.end_ = samples.back().time;
    target.vectors_ = std::move(samples);
    return target;
}

AngularVelocityTarget AngularVelocityTarget::fromSketch(std::vector<TimedVector> directions,
                                                        std::vector<TimedScalar> magnitudes)
{
    requireTimedCurve(directions, "the direction curve");
    requireTimedCurve(magnitudes, "the magnitude curve");
    for (std::size_t i = 0; i < directions.size(); ++i) {
        Eigen::Vector3d& d = directions[i].value;
        if (!d.allFinite() || d.norm() == 0.0)
            throw std::invalid_argument("direction " + std::to_string(i) + " is not a unit vector");
        d.normalize();
        if (i > 0 && arcAngle(directions[i - 1].value, d) > std::numbers::pi - kSameDirection)
            throw std::invalid_argument("directions " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                        " are opposite: no single arc joins them");
    }
    for (std::size_t i = 0; i < magnitudes.size(); ++i)
        if (!(magnitudes[i].value > 0.0) || !std::isfinite(magnitudes[i].value))
            throw std::invalid_argument("magnitude " + std::to_string(i) + " is not a positive finite number");
    AngularVelocityTarget target;
    target.start_ = std::max(directions.front().time, magnitudes.front().time);
    target.end_ = std::min(directions.back().time, magnitudes.back().time);
    if (!(target.start_ < target.end_))
        throw std::invalid_argument("the direction and magnitude curves do not overlap in time");
    target.vectors_ = std::move(directions);
    target.magnitudes_ = std::move(magnitudes);
    target.sketched_ = true;
    return target;
}

Eigen::Vector3d AngularVelocityTarget::at(double time) const
{
    SegmentCursor vectors;
    SegmentCursor magnitudes;
    return at(time, vectors, magnitudes);
}

Eigen::Vector3d AngularVelocityTarget::at(double time, SegmentCursor& vectors, SegmentCursor& magnitudes) const
{
    time = std::clamp(time, start_, end_);
    const std::size_t i = vectors.at(vectors_, time);
    const TimedVector& a = vectors_[i];
    const TimedVector& b = vectors_[i + 1];
    const double u = (time - a.time) / (b.time - a.time);
    if (!sketched_)
        return (1.0 - u) * a.value + u * b.value;
    const std::size_t k = magnitudes.at(magnitudes_, time);
    const TimedScalar& low = magnitudes_[k];
    const TimedScalar& high = magnitudes_[k + 1];
    const double v = (time - low.time) / (high.time - low.time);
    return ((1.0 - v) * low.value + v * high.value) * alongArc(a.value, b.value, u);
}

std::vector<TimedVector> spreadByArcLength(const std::vector<Eigen::Vector3d>& directions, double startTime,
                                           double endTime)
{
    if (directions.empty())
        throw std::invalid_argument("a direction curve needs at least one point");
    std::vector<Eigen::Vector3d> distinct{directions.front().normalized()};
    std::vector<double> lengths{0.0};
    for (const Eigen::Vector3d& direction : directions) {
        const Eigen::Vector3d unit = direction.normalized();
        const double angle = arcAngle(distinct.back(), unit);
        if (angle < kSameDirection)
            continue;
        distinct.push_back(unit);
        lengths.push_back(lengths.back() + angle);
    }
    if (distinct.size() == 1)
        return {{startTime, distinct.front()}, {endTime, distinct.front()}};
    std::vector<TimedVector> timed;
    for (std::size_t i = 0; i < distinct.size(); ++i)
        timed.push_back({startTime + (endTime - startTime) * lengths[i] / lengths.back(), distinct[i]});
    timed.back().time = endTime;  // exactly, whatever the rounding of the division
    return timed;
}

void checkPatternPointCount(std::size_t patternPoints, int repeat)
{
    const double points = static_cast<double>(repeat) * (static_cast<double>(patternPoints) - 1.0) + 1.0;
    if (!(points <= kMaxPatternPoints))
        throw std::invalid_argument(std::to_string(repeat) + " repeats of a pattern of " + std::to_string(patternPoints) +
                                    " points make " + formatNumber(points) + " points; the budget is " +
                                    formatNumber(kMaxPatternPoints));
}

std::vector<TimedVector> applyPattern(const std::vector<TimedVector>& directions,
                                      const std::vector<Eigen::Vector2d>& pattern, int repeat)
{
    if (pattern.size() < 2)
        throw std::invalid_argument("a pattern needs at least two points");
    if (repeat < 1)
        throw std::invalid_argument("a pattern must repeat at least once");
    checkPatternPointCount(pattern.size(), repeat);
    const Eigen::Vector2d first = pattern.front();
    const Eigen::Vector2d chord = pattern.back() - first;
    if (chord.x() == 0.0)
        throw std::invalid_argument("a pattern's first and last points must differ in x");
    const ArcLengthCurve curve(directions);
    if (curve.length() < kSameDirection)
        throw std::invalid_argument("a pattern needs a direction curve of some length");

    std::vector<double> drawn{0.0};  // the pattern's cumulative drawn length
    for (std::size_t k = 1; k < pattern.size(); ++k)
        drawn.push_back(drawn.back() + (pattern[k] - pattern[k - 1]).norm());
    const double period = curve.length() / repeat;
    const double scale = period / chord.x();  // pattern units to radians on the sphere

    std::vector<TimedVector> patterned;
    for (int r = 0; r < repeat; ++r) {
        for (std::size_t k = r == 0 ? 0 : 1; k < pattern.size(); ++k) {
            if (k > 0 && drawn[k] == drawn[k - 1])
                continue;  // a repeated pattern point would stand still in time
            const Eigen::Vector2d offset = pattern[k] - first;
            const double along = offset.x() / chord.x();
            const double across = scale * (offset.y() - along * chord.y());
            const ArcLengthCurve::Place place = curve.at((r + along) * period);
            const double time = curve.at((r + drawn[k] / drawn.back()) * period).time;
            patterned.push_back({time, std::cos(across) * place.point + std::sin(across) * place.across});
        }
    }
    return patterned;
}

} // namespace gyre::fit
