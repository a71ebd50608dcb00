#pragma once
// The sample projects bundled with Gyre (resources/samples), made in code so that every number in
// them has a reason: `gyre-samples DIR` writes them, and a test checks that the bundled files are
// what this code makes.

#include "model/scene.h"

#include <QString>

#include <vector>

namespace gyre::samples {

struct SampleScene {
    QString fileName;  // within resources/samples
    model::Scene scene;
};

// The sketch-editing paper's spinning top (its Fig. 3 and Table 1): 420 frames at 30 fps, 85 keys of
// a top precessing steadily about the vertical while it spins, and a sketch over it whose wobble
// pattern asks the fit for the nutation of a top on rough ground.
SampleScene spinningTop();

std::vector<SampleScene> allSamples();

} // namespace gyre::samples
