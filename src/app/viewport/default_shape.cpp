#include "app/viewport/default_shape.h"

#include "model/primitive_meshes.h"

namespace gyre::app {

const model::Mesh& defaultShapeMesh()
{
    static const model::Mesh shape = model::primitiveMesh(model::Primitive::Block);
    return shape;
}

} // namespace gyre::app
