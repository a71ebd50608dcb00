#pragma once
// A ballistic track's chosen free flights as the project file holds them: one integer per span from the first,
// Keyframe::flightSolution of each span's first key, trailing defaults left out (a track that chose none writes
// an empty list, as files before ballistic interpolation read).

#include "model/scene.h"

#include <vector>

namespace gyre::model {

class JsonField;

// The choices of every span up to the last that chose a flight.
std::vector<int> flightSolutions(const std::vector<Keyframe>& keys);

// Sets the keys' choices from `field`, an array of at most one integer ≥ −1 per span. Throws FieldError naming
// the field for more choices than spans or a value out of range.
void setFlightSolutions(std::vector<Keyframe>& keys, const JsonField& field);

} // namespace gyre::model
