#pragma once
// The time map of a keyed polyscrew: time t to the polyscrew's parameter p(t), with p(tᵢ) = i at
// key i. ScrewBender's introduction gives the construction: values p(tᵢ) = i and derivatives
// p′(tᵢ) = vᵢ interpolated by a C¹ piecewise cubic (cubic Hermite on each span). A motion X(p)
// smooth in its parameter then plays with velocity X′(p)·p′(t), continuous across every key
// whatever the key times; a map linear per span would scale the velocity by the ratio of the
// neighbouring spans at each key.
//
// vᵢ = 2/(tᵢ₊₁ − tᵢ₋₁): the parameter's advance over the two spans around key i, per second. At the
// ends of an open track the one span's 1/(tᵢ₊₁ − tᵢ). With equal spans every vᵢ is the secant slope
// and the map is linear. Each span's end slopes lie below twice its secant slope 1/Δ, inside
// Fritsch and Carlson's region (both below three times the secant), so p increases strictly.
//
// A cyclic track closes with a span from the last key back to the first lasting the mean of the
// others, (tₙ₋₁ − t₀)/(n − 1); the period is T = n·(tₙ₋₁ − t₀)/(n − 1) and time t plays as
// t₀ + ((t − t₀) mod T), before t₀ as well as after. Its first and last keys take their slopes from
// the closing span as a neighbour, so the cycle is C¹ where it wraps.

#include <cstddef>
#include <vector>

namespace gyre {

class KeyTimeMap {
public:
    // Throws std::invalid_argument for no times, or times that are not finite or do not strictly
    // increase.
    KeyTimeMap(const std::vector<double>& keyTimes, bool cyclic);

    // p(t): in [0, n − 1] for an open track, held outside the keys; in [0, n) for a cyclic one.
    double parameterAt(double time) const;
    // p′(t), parameter per second: zero where an open track holds its end keys.
    double rateAt(double time) const;
    // The t in [t₀, tₙ₋₁] (open) or [t₀, t₀ + T) (cyclic) with p(t) = parameter, for a parameter in
    // the range parameterAt gives; clamped outside it.
    double timeAt(double parameter) const;

    // T for a cyclic track, tₙ₋₁ − t₀ for an open one.
    double period() const { return knots_.back() - knots_.front(); }

private:
    struct SpanPoint {
        std::size_t span;
        double u; // (t − start)/(span length), in [0, 1]
    };
    // The span a time falls in, after a cycle's wrap; u clamped to [0, 1] outside an open track.
    SpanPoint spanAt(double time) const;
    // The cubic of span k at u ∈ [0, 1], less k: h₁₀(u)·Δ·vₖ + h₀₁(u) + h₁₁(u)·Δ·vₖ₊₁ (hermiteBasis).
    double spanValue(std::size_t span, double u) const;
    double spanSlope(std::size_t span, double u) const; // its derivative in u
    double spanLength(std::size_t span) const { return knots_[span + 1] - knots_[span]; }

    std::vector<double> knots_; // the key times, and a cycle's closing time t₀ + T
    std::vector<double> rates_; // p′ at each knot
    bool cyclic_;
};

} // namespace gyre
