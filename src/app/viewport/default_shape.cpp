#include "app/viewport/default_shape.h"

#include "model/primitive_meshes.h"

#include <array>

namespace gyre::app {

namespace {

model::Mesh makeBone()
{
    // Blender's octahedral bone along +x: the head at the origin, the tail at 1, widest (a square of
    // half-width kWaist) at kWaist along.
    constexpr float kWaist = 0.1F;
    using Corner = Eigen::Vector3f;
    const Corner head(0.0F, 0.0F, 0.0F), tail(1.0F, 0.0F, 0.0F);
    const std::array<Corner, 4> waist{Corner(kWaist, -kWaist, 0.0F), Corner(kWaist, 0.0F, -kWaist),
                                      Corner(kWaist, kWaist, 0.0F), Corner(kWaist, 0.0F, kWaist)};
    model::Mesh mesh;
    for (std::size_t i = 0; i < waist.size(); ++i) {
        const Corner& a = waist[i];
        const Corner& b = waist[(i + 1) % waist.size()];
        model::addFace(mesh, {head, b, a});
        model::addFace(mesh, {tail, a, b});
    }
    return mesh;
}

model::Mesh makeEmptyHull()
{
    // Eight faces, one per octant, each counter-clockwise seen from outside: (x, y, z) when the signs'
    // product is positive, else (x, z, y).
    const float l = static_cast<float>(kEmptyAxisLength);
    model::Mesh mesh;
    for (const float sx : {l, -l})
        for (const float sy : {l, -l})
            for (const float sz : {l, -l}) {
                const Eigen::Vector3f x(sx, 0.0F, 0.0F), y(0.0F, sy, 0.0F), z(0.0F, 0.0F, sz);
                if (sx * sy * sz > 0.0F)
                    model::addFace(mesh, {x, y, z});
                else
                    model::addFace(mesh, {x, z, y});
            }
    return mesh;
}

} // namespace

const model::Mesh& emptyHullMesh()
{
    static const model::Mesh hull = makeEmptyHull();
    return hull;
}

const model::Mesh& boneMesh()
{
    static const model::Mesh bone = makeBone();
    return bone;
}

const model::Mesh& defaultShapeMesh()
{
    static const model::Mesh shape = model::primitiveMesh(model::Primitive::Block);
    return shape;
}

} // namespace gyre::app
