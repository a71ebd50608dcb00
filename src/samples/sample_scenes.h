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

// The sketch-editing paper's other Table 1 animations, each keyed by Hermite interpolation with a
// sketch over part of it that asks the fit for a visible change:
// a letter M tumbling, its axis bent along a curve and its speed raised (Fig. 2; 240 frames, 49 keys);
SampleScene letterM();
// a hat tossed twice, flipping, its second flip leaning into a cartwheel (240 frames, 49 keys);
SampleScene hat();
// a leaf tumbling slowly down and sideways, a gust in the middle (800 frames, 81 keys);
SampleScene fallingLeaf();
// a pen spun and tossed, whirling faster at the top (121 frames, 25 keys; only the speed sketched).
SampleScene pen();

// ScrewBender's examples, cyclic screw tracks: the two-pose pendulum and the spinning block of its
// Fig. 7, and a cycle that leaves the plane like the bunny of its Fig. 12.
SampleScene pendulum();
SampleScene spinningBlock();
SampleScene critterCycle();

// Issue 24's free flights, each a ballistic track keyed at launch and landing only, its body's mass properties
// from its mesh: a T-handle tossed spinning about its intermediate axis, which flips (the Dzhanibekov effect); a
// coin flipped end over end; a book thrown flat.
SampleScene tHandle();
SampleScene flippedCoin();
SampleScene thrownBook();
std::vector<SampleScene> flightSamples();

// The five sketched samples above, as keyed and sketched, before any fit.
std::vector<SampleScene> sketchedSamples();

// The sample with its sketch's fit applied as the Fit button applies it (ApplyFitResultCommand with
// model::appliedFitResult): the bundled file opens on the paper's edited motion, its keyed motion
// drawn as "before fit", and Remove fit returns to it. Throws std::runtime_error naming the sample if
// the fit does not converge.
SampleScene withFitApplied(SampleScene sample);

// Every bundled sample as gyre-samples writes it: the sketched ones with their fit applied, then
// ScrewBender's, then the free flights.
std::vector<SampleScene> allSamples();

} // namespace gyre::samples
