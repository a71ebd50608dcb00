#pragma once
// The direction half of the sketch-editing interface: a toolbar with the sphere view's tools over the
// sphere view, and the pattern pad below it while the Pattern tool is chosen.

#include "app/selection.h"
#include "model/document.h"

#include <QWidget>

namespace gyre::app {

class PatternPad;
class SphereView;

class DirectionSketchPanel : public QWidget {
    Q_OBJECT

public:
    DirectionSketchPanel(model::Document& document, Selection& selection, QWidget* parent = nullptr);

    SphereView* sphereView() const { return sphereView_; }
    PatternPad* patternPad() const { return patternPad_; }

private:
    SphereView* sphereView_;
    PatternPad* patternPad_;
};

} // namespace gyre::app
