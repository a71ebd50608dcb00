#pragma once
// Positions through timed keys, linear or cubic, to go with an orientation curve: a key's pose is its
// orientation and its position.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace gyre {

// The cubic Hermite basis at u ∈ [0, 1] and its first two derivatives in u:
//   h₀₀ = 2u³ − 3u² + 1,  h₁₀ = u³ − 2u² + u,  h₀₁ = −2u³ + 3u²,  h₁₁ = u³ − u²
// weighting, in this order, the start value, the start slope, the end value and the end slope.
struct HermiteBasis {
    std::array<double, 4> value;
    std::array<double, 4> first;
    std::array<double, 4> second;
};
HermiteBasis hermiteBasis(double u);

struct PositionKey {
    double time = 0.0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

class PositionCurve {
public:
    enum class Shape { Linear, Cubic };

    // Throws std::invalid_argument unless there is at least one key and times strictly increase.
    // A cubic curve is the Hermite spline with slopes (pᵢ₊₁ − pᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁), one-sided at the
    // ends: the estimate the Hermite quaternion spline uses for orientations.
    PositionCurve(std::vector<PositionKey> keys, Shape shape);

    // Held at the end positions outside the key span.
    Eigen::Vector3d at(double time) const;
    // d/dt of at(): zero outside the key span; at a key of a linear curve, the slope of the span after it.
    Eigen::Vector3d velocity(double time) const;

private:
    std::vector<PositionKey> keys_;
    std::vector<Eigen::Vector3d> slopes_; // empty for a linear curve
};

} // namespace gyre
