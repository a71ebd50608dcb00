#include "app/viewport/default_shape.h"

#include <array>

namespace gyre::app {

namespace {

using Corner = Eigen::Vector3f;

// A flat polygon, its corners counter-clockwise seen from outside, fanned into triangles.
template <std::size_t N>
void addFace(model::Mesh& mesh, const std::array<Corner, N>& corners)
{
    const Eigen::Vector3f normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (const Corner& corner : corners) {
        mesh.positions.push_back(corner);
        mesh.normals.push_back(normal);
    }
    for (std::uint32_t i = 1; i + 1 < N; ++i)
        mesh.indices.insert(mesh.indices.end(), {first, first + i, first + i + 1});
}

// Which faces addBox leaves out: the face that another part covers, so that the whole stays closed.
enum class BoxOpening { None, PlusX };

void addBox(model::Mesh& mesh, const Corner& low, const Corner& high, BoxOpening opening = BoxOpening::None)
{
    const auto corner = [&](int x, int y, int z) {
        return Corner(x != 0 ? high.x() : low.x(), y != 0 ? high.y() : low.y(), z != 0 ? high.z() : low.z());
    };
    addFace<4>(mesh, {corner(0, 0, 0), corner(0, 1, 0), corner(1, 1, 0), corner(1, 0, 0)}); // −z
    addFace<4>(mesh, {corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)}); // +z
    addFace<4>(mesh, {corner(0, 0, 0), corner(1, 0, 0), corner(1, 0, 1), corner(0, 0, 1)}); // −y
    addFace<4>(mesh, {corner(0, 1, 0), corner(0, 1, 1), corner(1, 1, 1), corner(1, 1, 0)}); // +y
    addFace<4>(mesh, {corner(0, 0, 0), corner(0, 0, 1), corner(0, 1, 1), corner(0, 1, 0)}); // −x
    if (opening != BoxOpening::PlusX)
        addFace<4>(mesh, {corner(1, 0, 0), corner(1, 1, 0), corner(1, 1, 1), corner(1, 0, 1)}); // +x
}

model::Mesh makeDefaultShape()
{
    model::Mesh mesh;
    // The body, 1.2 long (x), 0.6 wide (y), 0.4 high (z), centred on the origin, open at +x where
    // the nose closes it.
    addBox(mesh, Corner(-0.6F, -0.3F, -0.2F), Corner(0.6F, 0.3F, 0.2F), BoxOpening::PlusX);
    // The nose: a pyramid on the +x end, its tip 0.4 ahead.
    const Corner tip(1.0F, 0.0F, 0.0F);
    const Corner a(0.6F, -0.3F, -0.2F), b(0.6F, 0.3F, -0.2F), c(0.6F, 0.3F, 0.2F), d(0.6F, -0.3F, 0.2F);
    addFace<3>(mesh, {a, b, tip});
    addFace<3>(mesh, {b, c, tip});
    addFace<3>(mesh, {c, d, tip});
    addFace<3>(mesh, {d, a, tip});
    // The fin: on top, towards the back, so up and back are told apart from down and front.
    addBox(mesh, Corner(-0.6F, -0.05F, 0.2F), Corner(-0.2F, 0.05F, 0.5F));
    return mesh;
}

model::Mesh makeBone()
{
    // Blender's octahedral bone along +x: the head at the origin, the tail at 1, widest (a square of
    // half-width kWaist) at kWaist along.
    constexpr float kWaist = 0.1F;
    const Corner head(0.0F, 0.0F, 0.0F), tail(1.0F, 0.0F, 0.0F);
    const std::array<Corner, 4> waist{Corner(kWaist, -kWaist, 0.0F), Corner(kWaist, 0.0F, -kWaist),
                                      Corner(kWaist, kWaist, 0.0F), Corner(kWaist, 0.0F, kWaist)};
    model::Mesh mesh;
    for (std::size_t i = 0; i < waist.size(); ++i) {
        const Corner& a = waist[i];
        const Corner& b = waist[(i + 1) % waist.size()];
        addFace<3>(mesh, {head, b, a});
        addFace<3>(mesh, {tail, a, b});
    }
    return mesh;
}

} // namespace

const model::Mesh& boneMesh()
{
    static const model::Mesh bone = makeBone();
    return bone;
}

const model::Mesh& defaultShapeMesh()
{
    static const model::Mesh shape = makeDefaultShape();
    return shape;
}

} // namespace gyre::app
