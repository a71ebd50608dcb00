#pragma once
// The target angular velocity ωˢ(t) of the fit, world frame, rad/s. Either samples of ω, linear
// between them, or the artist's sketch: a direction curve on the unit sphere times a magnitude
// curve over time (the sketch-editing paper's two views).

#include "core/timed_keys.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace gyre::fit {

struct TimedVector {
    double time = 0.0;
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

struct TimedScalar {
    double time = 0.0;
    double value = 0.0;
};

class AngularVelocityTarget {
public:
    // ω linear between samples. At least two samples, strictly increasing times, finite values;
    // throws std::invalid_argument otherwise.
    static AngularVelocityTarget fromSamples(std::vector<TimedVector> samples);

    // ω(t) = m(t)·d(t): d along the great arc between consecutive timed unit directions, m linear
    // between magnitude samples. Directions must be unit (normalised here) with no two consecutive
    // ones opposite, magnitudes positive; each curve at least two samples with increasing times.
    // The target spans the overlap of the two curves' spans, which must not be empty.
    static AngularVelocityTarget fromSketch(std::vector<TimedVector> directions, std::vector<TimedScalar> magnitudes);

    // Clamped to the end values outside [startTime(), endTime()].
    Eigen::Vector3d at(double time) const;

    // at() for times that mostly increase, as the fit's integrals read the target: each lookup starts
    // where the last one ended (SegmentCursor), not with a search of every sample. The same values as at().
    class Reader {
    public:
        explicit Reader(const AngularVelocityTarget& target)
            : target_(target)
        {
        }
        Eigen::Vector3d at(double time) { return target_.at(time, vectors_, magnitudes_); }

    private:
        const AngularVelocityTarget& target_;
        SegmentCursor vectors_;
        SegmentCursor magnitudes_;
    };
    double startTime() const { return start_; }
    double endTime() const { return end_; }

private:
    AngularVelocityTarget() = default;
    Eigen::Vector3d at(double time, SegmentCursor& vectors, SegmentCursor& magnitudes) const;

    // Samples of ω when given that way; otherwise the directions, with magnitudes_ alongside.
    std::vector<TimedVector> vectors_;
    std::vector<TimedScalar> magnitudes_;
    bool sketched_ = false;
    double start_ = 0.0;
    double end_ = 0.0;
};

// Unit directions spread over [startTime, endTime] in proportion to arc length along the great arcs
// joining them; points that repeat the previous one are dropped. A curve of no length (one point, or
// one repeated) holds its direction over the whole span. Throws std::invalid_argument for no points.
std::vector<TimedVector> spreadByArcLength(const std::vector<Eigen::Vector3d>& directions, double startTime,
                                           double endTime);

// The most points a repeated pattern may make, repeat·(pattern points − 1) + 1: a million directions
// (32 MB), each also a target sample, so a fit over them stays within memory and minutes.
inline constexpr double kMaxPatternPoints = 1048576.0;

// Throws std::invalid_argument, naming the count, when `patternPoints` repeated `repeat` times make more
// than kMaxPatternPoints.
void checkPatternPointCount(std::size_t patternPoints, int repeat);

// The direction curve with a pattern repeated `repeat` times along it (the paper's spinning-top
// wobble). The pattern is a drawn 2-D shape, in any unit: its x runs along the curve, its y across.
// Each repetition takes 1/repeat of the curve's arc length, and the shape is scaled uniformly so that
// its x extent fills that; its ends sit on the curve (y is measured from the line through its first
// and last points), so repetitions join. Time advances along each repetition with the pattern's own
// drawn length, so a pattern that loops back still moves forward in time. Throws
// std::invalid_argument for a pattern of fewer than two points, equal first and last x, repeat < 1,
// or a direction curve of no length.
std::vector<TimedVector> applyPattern(const std::vector<TimedVector>& directions,
                                      const std::vector<Eigen::Vector2d>& pattern, int repeat);

} // namespace gyre::fit
