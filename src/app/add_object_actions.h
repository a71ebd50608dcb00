#pragma once
// Object ▸ Add: a new object of one of the primitive shapes (model/primitive_meshes.h), or an empty
// (SceneObject::empty: no mesh, drawn as its axes), at the world origin with no keys, selected, in one
// undo step. Its name is the shape's, made unique as Blender makes it ("Box", then "Box.001").

#include "app/selection.h"
#include "model/document.h"
#include "model/primitive_meshes.h"

#include <QObject>

class QMenu;

namespace gyre::app {

class AddObjectActions : public QObject {
    Q_OBJECT

public:
    // Fills `menu` with one action per primitive, then Empty.
    AddObjectActions(model::Document& document, Selection& selection, QMenu& menu, QObject* parent = nullptr);

    void add(model::Primitive primitive);
    void addEmpty();

private:
    // Adds `object` named after its shape, made unique, as the undo step "Add <shape>", and selects it.
    void addObject(model::SceneObject object, const QString& shapeName);

    model::Document& document_;
    Selection& selection_;
};

} // namespace gyre::app
