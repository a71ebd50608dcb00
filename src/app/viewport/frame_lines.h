#pragma once
// The lines a viewport frame draws, by how they are drawn, as the line shader reads them. No OpenGL,
// so the geometry that fills them can be built and tested without a context.

#include <Eigen/Core>

#include <vector>

namespace gyre::app {

struct Rgba {
    float r, g, b, a;
};

// The colours of the x, y and z axes wherever lines show them: the ground's axes, the control
// poses' frames, the handles.
inline constexpr Rgba kAxisColors[3] = {{0.95F, 0.30F, 0.30F, 1.0F}, {0.35F, 0.85F, 0.35F, 1.0F}, {0.35F, 0.55F, 1.0F, 1.0F}};

// The selected object, its mesh or its lines (an empty's axes).
inline constexpr Rgba kSelectedColor{0.98F, 0.63F, 0.22F, 1.0F};

// As the line shader reads it.
struct LineVertex {
    float position[3];
    float color[4];
};

inline LineVertex lineVertex(const Eigen::Vector3d& point, const Rgba& color)
{
    return {{float(point.x()), float(point.y()), float(point.z())}, {color.r, color.g, color.b, color.a}};
}

// A run of FrameLines::vertices drawn as one primitive.
struct LineRange {
    int first = 0;
    int count = 0;
};

// The lines of one frame, by how they are drawn.
struct FrameLines {
    std::vector<LineVertex> vertices;
    LineRange grid, axes;             // lines, depth-tested, before the meshes
    bool drawPaths = false;           // the centre paths as last uploaded (SceneRenderer::setPaths), with the grid
    LineRange handles, handlePoints;  // lines and points, on top of everything
    LineRange physics;                // lines on top: angular momentum, principal axes
};

} // namespace gyre::app
