#include "app/sketch/direction_sketch_panel.h"

#include "app/sketch/pattern_pad.h"
#include "app/sketch/sphere_view.h"

#include <QToolBar>
#include <QVBoxLayout>

namespace gyre::app {

DirectionSketchPanel::DirectionSketchPanel(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , sphereView_(new SphereView(document, selection, this))
    , patternPad_(new PatternPad(document, selection, this))
{
    auto* toolBar = new QToolBar(this);
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    toolBar->addActions({sphereView_->drawAction(), sphereView_->eraseAction(), sphereView_->patternAction()});
    toolBar->addSeparator();
    toolBar->addAction(sphereView_->resetViewAction());

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(toolBar);
    layout->addWidget(sphereView_, 1);
    layout->addWidget(patternPad_);

    // The tools' shortcuts work anywhere in the panel, the pad included.
    addActions(sphereView_->actions());
    patternPad_->setVisible(sphereView_->tool() == SphereView::Tool::Pattern);
    connect(sphereView_, &SphereView::toolChanged, patternPad_,
            [this](SphereView::Tool tool) { patternPad_->setVisible(tool == SphereView::Tool::Pattern); });
}

} // namespace gyre::app
