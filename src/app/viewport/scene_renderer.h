#pragma once
// The viewport's OpenGL side: the mesh and line shaders, each mesh's buffers (uploaded on first use,
// dropped when no object holds the mesh any more), the instance buffers of the trail and the control
// poses, the centre paths (uploaded when they change), and one frame's drawing in its order: lines under the meshes, the objects, the translucent
// trail, control poses and ghost, and the handles on top. It decides nothing about what is shown:
// the viewport gathers that from the document, its motion and the selection.

#include "app/viewport/frame_lines.h"
#include "app/viewport/skeleton.h"
#include "model/scene_motion.h"
#include "core/pose.h"
#include "model/scene.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

namespace gyre::app {

// How the scene's objects are shaded: solid or as the edges of their triangles (wireframe), opaque
// or see-through (X-ray).
struct Shading {
    bool wireframe = false;
    bool xray = false;
};

// One object's copies among the trail's instances (SceneRenderer::setTrail): `count` from `first`, in `frame`.
struct TrailInstances {
    const model::SceneObject* object = nullptr;
    Pose frame; // the world frame of the copies: the parent's for a screw track's, else the world's
    int first = 0;
    int count = 0;
};

// The meshes of one frame: every object of the scene at its current time (joints as their bones),
// the selected objects' trails, and the active object's control poses (its keys) and ghost.
struct FrameMeshes {
    const model::Scene* scene = nullptr;
    const model::SceneMotion* motion = nullptr;
    const Skeleton* skeleton = nullptr; // updated for the scene at its current time
    Shading shading;
    const model::SceneObject* selected = nullptr;
    Pose selectedParentFrame; // the world frame of the selected object's keys
    std::vector<TrailInstances> trails; // as last uploaded with setTrail; none while the trail is hidden
    bool controlPoses = false;
    std::optional<std::size_t> highlightedKey;
    std::optional<Pose> ghost; // the selected object's original world pose, where it is drawn
};

class SceneRenderer final : protected QOpenGLExtraFunctions {
public:
    // Control poses are drawn as small copies of their object.
    static constexpr double kControlPoseScale = 0.6;

    SceneRenderer() = default;
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    // With the widget's context current: builds the shaders and buffers.
    void initialize();
    // With the context current: frees everything initialize and drawing made. Safe to call twice.
    void release();
    bool isInitialized() const { return meshProgram_ != nullptr; }

    // The radius of the bounding sphere of the object's mesh about its origin (uploading the mesh).
    float meshRadius(const model::SceneObject& object) { return gpuMesh(object).radius; }
    // The next frame drops the buffers of meshes no object holds any more.
    void dropUnusedMeshesNextFrame() { meshesMayBeUnused_ = true; }
    // Uploads the trails' instances, every selected object's: column-major 4×4 matrices, each object's in the
    // frame its FrameMeshes::trails entry gives.
    void setTrail(const std::vector<float>& matrices);
    // Uploads the selected objects' centre paths, each drawn as one line strip in `color` in the frames whose
    // FrameLines::drawPaths is set, until the next call: they change with the motion or the selection, not with
    // the current time.
    void setPaths(const std::vector<std::vector<Eigen::Vector3f>>& paths, const Rgba& color);

    void drawFrame(const Eigen::Matrix4d& viewProjection, const Eigen::Vector3d& eye, const FrameLines& lines,
                   const FrameMeshes& meshes);

private:
    struct GpuMesh {
        std::shared_ptr<const model::Mesh> owner; // keeps the mesh, and so its address, alive; null for the default shape
        std::unique_ptr<QOpenGLVertexArrayObject> vertexArray;
        QOpenGLBuffer vertices{QOpenGLBuffer::VertexBuffer};
        QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
        QOpenGLBuffer skinVertices{QOpenGLBuffer::VertexBuffer}; // joint indices and weights, for a skinned mesh
        int indexCount = 0;
        float radius = 1.0F; // of the bounding sphere about the local origin, in the bind pose
        std::optional<GLenum> frontFace; // GL_CCW or GL_CW for a closed mesh, whose back faces are culled
    };

    GpuMesh& gpuMesh(const model::SceneObject& object);
    // owner: the shared pointer that holds `mesh`, or null for a shape built once (default_shape.h).
    GpuMesh& gpuMesh(const model::Mesh& mesh, const std::shared_ptr<const model::Mesh>& owner);
    void drawObjects(const FrameMeshes& meshes);
    // Uploads the joint matrices of the skinned `object` (model/skinning.h) at the scene's time.
    void uploadJointMatrices(const model::SceneObject& object, const FrameMeshes& meshes);
    void dropUnusedMeshes();
    // Draws `instanceCount` instances from `firstInstance` of the buffer.
    void drawMesh(GpuMesh& mesh, QOpenGLBuffer& instances, int instanceCount, int firstInstance = 0);
    void drawLines(GLenum mode, LineRange range);
    void uploadLines(const FrameLines& lines);
    void uploadControlPoses(const model::SceneObject& object);
    void setMeshColors(const Rgba& start, const Rgba& end);

    QOpenGLFunctions_3_3_Core* desktopGl_ = nullptr; // for glPolygonMode, which OpenGL ES lacks
    std::unique_ptr<QOpenGLShaderProgram> meshProgram_;
    std::unique_ptr<QOpenGLShaderProgram> lineProgram_;
    std::unordered_map<const model::Mesh*, GpuMesh> gpuMeshes_;
    bool meshesMayBeUnused_ = false;
    bool cullBackFaces_ = true; // of closed meshes; not while the objects are drawn in X-ray or wireframe
    QOpenGLBuffer identityInstance_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer trailInstances_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer controlPoseInstances_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer lineBuffer_{QOpenGLBuffer::VertexBuffer};
    // The buffer of the mesh shader's uniform block of joint matrices, model::kMaxSkinJoints of them
    // (QOpenGLBuffer has no uniform buffer type).
    GLuint jointMatrices_ = 0;
    std::unique_ptr<QOpenGLVertexArrayObject> lineArray_;
    QOpenGLBuffer pathBuffer_{QOpenGLBuffer::VertexBuffer};
    std::unique_ptr<QOpenGLVertexArrayObject> pathArray_;
    std::vector<GLint> pathFirsts_;   // each path's first vertex in pathBuffer_
    std::vector<GLsizei> pathCounts_; // and its vertex count
    int trailInstanceCount_ = 0;
    std::vector<float> controlPoseMatrices_; // kept from frame to frame: drawing allocates nothing once grown
};

} // namespace gyre::app
