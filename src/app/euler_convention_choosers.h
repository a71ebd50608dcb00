#pragma once
// The pair of choosers of an Euler convention, its order and its frame, as the inspector and the graph
// editor show them: filled alike, read alike, and linked so that both views show angles of one
// convention.

#include "core/euler_angles.h"

class QComboBox;

namespace gyre::app {

// Fills `order` with the 12 orders (the six Tait-Bryan first, xyz at the top as DESIGN.md's default)
// and `frame` with extrinsic then intrinsic.
void fillConventionChoosers(QComboBox& order, QComboBox& frame);
// The convention the filled choosers show.
EulerConvention chosenConvention(const QComboBox& order, const QComboBox& frame);
// Sets the choosers to `convention` (their currentIndexChanged fires, activated does not).
void showConvention(QComboBox& order, QComboBox& frame, const EulerConvention& convention);
// Keeps two filled pairs of choosers showing the same convention, whichever one the artist changes.
void linkConventionChoosers(QComboBox& order, QComboBox& frame, QComboBox& otherOrder, QComboBox& otherFrame);

} // namespace gyre::app
