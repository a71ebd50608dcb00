#include "model/primitive_meshes.h"

#include <QCoreApplication>

#include <cmath>
#include <numbers>
#include <vector>

namespace gyre::model {

void addFace(Mesh& mesh, const std::vector<Eigen::Vector3f>& corners)
{
    const Eigen::Vector3f normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (const Eigen::Vector3f& corner : corners) {
        mesh.positions.push_back(corner);
        mesh.normals.push_back(normal);
    }
    for (std::uint32_t i = 1; i + 1 < corners.size(); ++i)
        mesh.indices.insert(mesh.indices.end(), {first, first + i, first + i + 1});
}

namespace {

using Corner = Eigen::Vector3f;

// The number of sides a round primitive is made of.
constexpr int kRoundSides = 32;

// Which faces addBox leaves out: the face that another part covers, so that the whole stays closed.
enum class BoxOpening { None, PlusX };

void addBox(Mesh& mesh, const Corner& low, const Corner& high, BoxOpening opening = BoxOpening::None)
{
    const auto corner = [&](int x, int y, int z) {
        return Corner(x != 0 ? high.x() : low.x(), y != 0 ? high.y() : low.y(), z != 0 ? high.z() : low.z());
    };
    addFace(mesh, {corner(0, 0, 0), corner(0, 1, 0), corner(1, 1, 0), corner(1, 0, 0)}); // −z
    addFace(mesh, {corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)}); // +z
    addFace(mesh, {corner(0, 0, 0), corner(1, 0, 0), corner(1, 0, 1), corner(0, 0, 1)}); // −y
    addFace(mesh, {corner(0, 1, 0), corner(0, 1, 1), corner(1, 1, 1), corner(1, 1, 0)}); // +y
    addFace(mesh, {corner(0, 0, 0), corner(0, 0, 1), corner(0, 1, 1), corner(0, 1, 0)}); // −x
    if (opening != BoxOpening::PlusX)
        addFace(mesh, {corner(1, 0, 0), corner(1, 1, 0), corner(1, 1, 1), corner(1, 0, 1)}); // +x
}

Mesh block()
{
    Mesh mesh;
    // The body, 1.2 long (x), 0.6 wide (y), 0.4 high (z), centred on the origin, open at +x where
    // the nose closes it.
    addBox(mesh, Corner(-0.6F, -0.3F, -0.2F), Corner(0.6F, 0.3F, 0.2F), BoxOpening::PlusX);
    // The nose: a pyramid on the +x end, its tip 0.4 ahead.
    const Corner tip(1.0F, 0.0F, 0.0F);
    const Corner a(0.6F, -0.3F, -0.2F), b(0.6F, 0.3F, -0.2F), c(0.6F, 0.3F, 0.2F), d(0.6F, -0.3F, 0.2F);
    addFace(mesh, {a, b, tip});
    addFace(mesh, {b, c, tip});
    addFace(mesh, {c, d, tip});
    addFace(mesh, {d, a, tip});
    // The fin: on top, towards the back, so up and back are told apart from down and front.
    addBox(mesh, Corner(-0.6F, -0.05F, 0.2F), Corner(-0.2F, 0.05F, 0.5F));
    return mesh;
}

// The point at `angle` on the circle of `radius` about the x axis at `x`: x is the round shapes'
// axis, as the block's nose is, so an arrow points where a block does.
Corner onCircle(float x, float radius, double angle)
{
    return {x, radius * static_cast<float>(std::cos(angle)), radius * static_cast<float>(std::sin(angle))};
}

// The angle of a side's first corner; the last side ends where the first begins, at exactly the
// same corner, so that the surface closes.
double sideAngle(int side) { return 2.0 * std::numbers::pi * (side % kRoundSides) / kRoundSides; }

// A round cap at `x` of `radius`, facing −x (`facingPlusX` false) or +x.
void addCap(Mesh& mesh, float x, float radius, bool facingPlusX)
{
    std::vector<Corner> corners;
    for (int side = 0; side < kRoundSides; ++side) {
        // Counter-clockwise seen from +x is increasing angle (y towards z).
        const int index = facingPlusX ? side : kRoundSides - 1 - side;
        corners.push_back(onCircle(x, radius, sideAngle(index)));
    }
    addFace(mesh, corners);
}

// The side of a frustum along +x, from `radius0` at `x0` to `radius1` at `x1` (0 for a point).
void addRoundSide(Mesh& mesh, float x0, float radius0, float x1, float radius1)
{
    for (int side = 0; side < kRoundSides; ++side) {
        const double a = sideAngle(side);
        const double b = sideAngle(side + 1);
        if (radius1 == 0.0F)
            addFace(mesh, {onCircle(x0, radius0, a), onCircle(x0, radius0, b), Corner(x1, 0.0F, 0.0F)});
        else
            addFace(mesh, {onCircle(x0, radius0, a), onCircle(x0, radius0, b), onCircle(x1, radius1, b),
                           onCircle(x1, radius1, a)});
    }
}

Mesh disc()
{
    // A coin: 1 across, 0.1 thick, its faces along ±x.
    Mesh mesh;
    addCap(mesh, -0.05F, 0.5F, false);
    addRoundSide(mesh, -0.05F, 0.5F, 0.05F, 0.5F);
    addCap(mesh, 0.05F, 0.5F, true);
    return mesh;
}

Mesh cone()
{
    // 1 long, 1 across at its base, its tip along +x; the origin halfway.
    Mesh mesh;
    addCap(mesh, -0.5F, 0.5F, false);
    addRoundSide(mesh, -0.5F, 0.5F, 0.5F, 0.0F);
    return mesh;
}

Mesh arrow()
{
    // A shaft 0.1 across from the origin to 0.7, and a head 0.3 across to the tip at 1, along +x.
    Mesh mesh;
    addCap(mesh, 0.0F, 0.05F, false);
    addRoundSide(mesh, 0.0F, 0.05F, 0.7F, 0.05F);
    // The underside of the head, a ring between the shaft and the head's rim, as a fan of quads.
    for (int side = 0; side < kRoundSides; ++side) {
        const double a = sideAngle(side);
        const double b = sideAngle(side + 1);
        addFace(mesh, {onCircle(0.7F, 0.05F, a), onCircle(0.7F, 0.05F, b), onCircle(0.7F, 0.15F, b),
                       onCircle(0.7F, 0.15F, a)});
    }
    addRoundSide(mesh, 0.7F, 0.15F, 1.0F, 0.0F);
    return mesh;
}

} // namespace

Mesh primitiveMesh(Primitive primitive)
{
    switch (primitive) {
    case Primitive::Block:
        return block();
    case Primitive::Box:
    {
        Mesh mesh;
        addBox(mesh, Corner::Constant(-0.5F), Corner::Constant(0.5F));
        return mesh;
    }
    case Primitive::Disc:
        return disc();
    case Primitive::Cone:
        return cone();
    case Primitive::Arrow:
        return arrow();
    }
    return {};
}

QString primitiveName(Primitive primitive)
{
    const auto translated = [](const char* name) { return QCoreApplication::translate("gyre::model::Primitive", name); };
    switch (primitive) {
    case Primitive::Block:
        return translated(QT_TRANSLATE_NOOP("gyre::model::Primitive", "Block"));
    case Primitive::Box:
        return translated(QT_TRANSLATE_NOOP("gyre::model::Primitive", "Box"));
    case Primitive::Disc:
        return translated(QT_TRANSLATE_NOOP("gyre::model::Primitive", "Disc"));
    case Primitive::Cone:
        return translated(QT_TRANSLATE_NOOP("gyre::model::Primitive", "Cone"));
    case Primitive::Arrow:
        return translated(QT_TRANSLATE_NOOP("gyre::model::Primitive", "Arrow"));
    }
    return {};
}

} // namespace gyre::model
