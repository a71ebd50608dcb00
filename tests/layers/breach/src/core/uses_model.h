#pragma once
// A core header that includes the model: what the layer check must refuse.
#include "core/pose.h"
#include "model/scene.h"
