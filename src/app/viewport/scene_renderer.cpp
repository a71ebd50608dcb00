#include "app/viewport/scene_renderer.h"

#include "app/viewport/default_shape.h"
#include "app/viewport/mesh_winding.h"
#include "app/viewport/pose_matrix.h"
#include "model/skinning.h"
#include "model/value_checks.h"

#include <QMatrix4x4>
#include <QOpenGLContext>
#include <QOpenGLVersionFunctionsFactory>
#include <QVector3D>
#include <QVector4D>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace gyre::app {

namespace {

// Mesh shader attributes: position, normal, the instance's model matrix as four columns, then a
// skinned mesh's joint indices and weights.
constexpr GLuint kPositionAttribute = 0;
constexpr GLuint kNormalAttribute = 1;
constexpr GLuint kInstanceAttribute = 2;
constexpr GLuint kJointsAttribute = 6;
constexpr GLuint kWeightsAttribute = 7;
constexpr GLuint kJointMatricesBinding = 0; // the uniform block's binding point
constexpr float kHandlePointSize = 11.0F;

constexpr Rgba kBackground{0.16F, 0.17F, 0.19F, 1.0F};
constexpr Rgba kObjectColor{0.62F, 0.66F, 0.72F, 1.0F};
constexpr Rgba kTrailStart{0.30F, 0.55F, 0.95F, 0.3F};
constexpr Rgba kTrailEnd{0.55F, 0.90F, 0.75F, 0.3F};
constexpr Rgba kControlPoseColor{0.95F, 0.95F, 0.98F, 0.35F};
constexpr Rgba kSelectedKeyColor{1.0F, 0.85F, 0.30F, 0.6F};
constexpr Rgba kGhostColor{0.85F, 0.85F, 1.0F, 0.25F};
constexpr float kXrayAlpha = 0.35F; // the objects' opacity in X-ray shading

QVector4D toVector(const Rgba& color)
{
    return {color.r, color.g, color.b, color.a};
}

QMatrix4x4 toQMatrix(const Eigen::Matrix4d& matrix)
{
    // QMatrix4x4 takes its 16 values in row-major order.
    const Eigen::Matrix<float, 4, 4, Eigen::RowMajor> rows = matrix.cast<float>();
    return QMatrix4x4(rows.data());
}

// The front face of a closed mesh, whose back faces the viewport culls; none for an open mesh.
std::optional<GLenum> cullableFrontFace(const model::Mesh& mesh)
{
    switch (meshWinding(mesh)) {
    case MeshWinding::CounterClockwise:
        return GL_CCW;
    case MeshWinding::Clockwise:
        return GL_CW;
    case MeshWinding::Open:
        break;
    }
    return std::nullopt;
}

} // namespace

void SceneRenderer::initialize()
{
    initializeOpenGLFunctions();
    desktopGl_ = QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_3_3_Core>(QOpenGLContext::currentContext());
    const auto buildProgram = [](const QString& name) {
        auto program = std::make_unique<QOpenGLShaderProgram>();
        // The shaders are compiled into the program: failing to build them is a broken build or a
        // driver without OpenGL 3.3, and the log says which.
        if (!program->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/shaders/%1.vert").arg(name))
            || !program->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/shaders/%1.frag").arg(name))
            || !program->link())
            qCritical("Viewport: the %s shaders do not build: %s", qPrintable(name), qPrintable(program->log()));
        return program;
    };
    meshProgram_ = buildProgram(QStringLiteral("mesh"));
    lineProgram_ = buildProgram(QStringLiteral("line"));
    if (const GLuint block = glGetUniformBlockIndex(meshProgram_->programId(), "JointMatrices"); block != GL_INVALID_INDEX)
        glUniformBlockBinding(meshProgram_->programId(), block, kJointMatricesBinding);
    glGenBuffers(1, &jointMatrices_);
    glBindBuffer(GL_UNIFORM_BUFFER, jointMatrices_);
    glBufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(model::kMaxSkinJoints * kFloatsPerMatrix * sizeof(float)),
                 nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);

    identityInstance_.create();
    identityInstance_.bind();
    const Eigen::Matrix4f identity = Eigen::Matrix4f::Identity();
    identityInstance_.allocate(identity.data(), kFloatsPerMatrix * sizeof(float));
    identityInstance_.release();
    for (QOpenGLBuffer* buffer : {&trailInstances_, &controlPoseInstances_, &lineBuffer_, &pathBuffer_}) {
        buffer->create();
        buffer->setUsagePattern(QOpenGLBuffer::DynamicDraw);
    }
    trailInstanceCount_ = 0;
    pathFirsts_.clear();
    pathCounts_.clear();

    // LineVertex as the line shader reads it, from `buffer`.
    const auto lineArray = [this](QOpenGLBuffer& buffer) {
        auto array = std::make_unique<QOpenGLVertexArrayObject>();
        array->create();
        array->bind();
        buffer.bind();
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex), reinterpret_cast<const void*>(offsetof(LineVertex, position)));
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(LineVertex), reinterpret_cast<const void*>(offsetof(LineVertex, color)));
        array->release();
        buffer.release();
        return array;
    };
    lineArray_ = lineArray(lineBuffer_);
    pathArray_ = lineArray(pathBuffer_);

    glEnable(GL_PROGRAM_POINT_SIZE);
    // Colour blends by the source's alpha; the framebuffer's own alpha stays 1 (1·a + 1·(1 − a)), as the
    // viewport's frame is read back as an opaque image (offscreen_gl_widget.h).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

void SceneRenderer::release()
{
    if (!meshProgram_)
        return;
    gpuMeshes_.clear();
    lineArray_.reset();
    pathArray_.reset();
    for (QOpenGLBuffer* buffer : {&identityInstance_, &trailInstances_, &controlPoseInstances_, &lineBuffer_, &pathBuffer_})
        buffer->destroy();
    glDeleteBuffers(1, &jointMatrices_);
    jointMatrices_ = 0;
    meshProgram_.reset();
    lineProgram_.reset();
}

SceneRenderer::GpuMesh& SceneRenderer::gpuMesh(const model::SceneObject& object)
{
    return gpuMesh(displayMesh(object), object.mesh);
}

SceneRenderer::GpuMesh& SceneRenderer::gpuMesh(const model::Mesh& mesh, const std::shared_ptr<const model::Mesh>& owner)
{
    const auto found = gpuMeshes_.find(&mesh);
    if (found != gpuMeshes_.end())
        return found->second;

    GpuMesh& gpu = gpuMeshes_[&mesh];
    gpu.owner = owner;
    // Interleaved position and normal. A mesh without normals gets each vertex's area-weighted mean
    // of its triangles' normals (the cross product's length is twice the area).
    std::vector<Eigen::Vector3f> normals = mesh.normals;
    if (normals.size() != mesh.positions.size()) {
        normals.assign(mesh.positions.size(), Eigen::Vector3f::Zero());
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const Eigen::Vector3f& a = mesh.positions[mesh.indices[i]];
            const Eigen::Vector3f normal = (mesh.positions[mesh.indices[i + 1]] - a).cross(mesh.positions[mesh.indices[i + 2]] - a);
            for (std::size_t k = 0; k < 3; ++k)
                normals[mesh.indices[i + k]] += normal;
        }
        for (Eigen::Vector3f& normal : normals)
            normal.normalize();
    }
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * 6);
    gpu.radius = 0.0F;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        interleaved.insert(interleaved.end(), mesh.positions[i].data(), mesh.positions[i].data() + 3);
        interleaved.insert(interleaved.end(), normals[i].data(), normals[i].data() + 3);
        gpu.radius = std::max(gpu.radius, mesh.positions[i].norm());
    }
    gpu.vertexArray = std::make_unique<QOpenGLVertexArrayObject>();
    gpu.vertexArray->create();
    gpu.vertexArray->bind();
    gpu.vertices.create();
    gpu.vertices.bind();
    gpu.vertices.allocate(interleaved.data(), static_cast<int>(interleaved.size() * sizeof(float)));
    constexpr int kStride = 6 * sizeof(float);
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, kStride, nullptr);
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, kStride, reinterpret_cast<const void*>(3 * sizeof(float)));
    for (GLuint column = 0; column < 4; ++column) {
        glEnableVertexAttribArray(kInstanceAttribute + column);
        glVertexAttribDivisor(kInstanceAttribute + column, 1);
    }
    if (const model::Skin& skin = mesh.skin; !skin.empty()) {
        // Per vertex: four uint16 joint indices, then four float weights.
        struct SkinVertex {
            std::array<std::uint16_t, 4> joints;
            std::array<float, 4> weights;
        };
        std::vector<SkinVertex> skinVertices(mesh.positions.size());
        for (std::size_t i = 0; i < skinVertices.size(); ++i) {
            skinVertices[i].joints = skin.vertexJoints[i];
            Eigen::Map<Eigen::Vector4f>(skinVertices[i].weights.data()) = skin.vertexWeights[i];
        }
        gpu.skinVertices.create();
        gpu.skinVertices.bind();
        gpu.skinVertices.allocate(skinVertices.data(), static_cast<int>(skinVertices.size() * sizeof(SkinVertex)));
        glEnableVertexAttribArray(kJointsAttribute);
        glVertexAttribIPointer(kJointsAttribute, 4, GL_UNSIGNED_SHORT, sizeof(SkinVertex),
                               reinterpret_cast<const void*>(offsetof(SkinVertex, joints)));
        glEnableVertexAttribArray(kWeightsAttribute);
        glVertexAttribPointer(kWeightsAttribute, 4, GL_FLOAT, GL_FALSE, sizeof(SkinVertex),
                              reinterpret_cast<const void*>(offsetof(SkinVertex, weights)));
        gpu.skinVertices.release();
    }
    gpu.indices.create();
    gpu.indices.bind();
    gpu.indices.allocate(mesh.indices.data(), static_cast<int>(mesh.indices.size() * sizeof(std::uint32_t)));
    gpu.indexCount = static_cast<int>(mesh.indices.size());
    gpu.frontFace = cullableFrontFace(mesh);
    gpu.vertexArray->release();
    gpu.vertices.release();
    gpu.indices.release();
    return gpu;
}

void SceneRenderer::dropUnusedMeshes()
{
    // A mesh only the cache still holds belongs to no object any more.
    std::erase_if(gpuMeshes_, [](const auto& entry) { return entry.second.owner && entry.second.owner.use_count() == 1; });
    meshesMayBeUnused_ = false;
}

void SceneRenderer::setTrail(const std::vector<float>& matrices)
{
    trailInstances_.bind();
    trailInstances_.allocate(matrices.data(), static_cast<int>(matrices.size() * sizeof(float)));
    trailInstances_.release();
    trailInstanceCount_ = static_cast<int>(matrices.size() / kFloatsPerMatrix);
}

void SceneRenderer::drawMesh(GpuMesh& mesh, QOpenGLBuffer& instances, int instanceCount, int firstInstance)
{
    mesh.vertexArray->bind();
    instances.bind();
    // The instances from the first one on: OpenGL 3.3 has no base instance, so the attributes start there.
    const std::size_t first = std::size_t(firstInstance) * kFloatsPerMatrix * sizeof(float);
    for (GLuint column = 0; column < 4; ++column)
        glVertexAttribPointer(kInstanceAttribute + column, 4, GL_FLOAT, GL_FALSE, kFloatsPerMatrix * sizeof(float),
                              reinterpret_cast<const void*>(first + column * 4 * sizeof(float)));
    meshProgram_->setUniformValue("uInstanceCount", instanceCount);
    if (mesh.frontFace && cullBackFaces_) {
        glEnable(GL_CULL_FACE);
        glFrontFace(*mesh.frontFace);
    }
    glDrawElementsInstanced(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr, instanceCount);
    glDisable(GL_CULL_FACE);
    instances.release();
    mesh.vertexArray->release();
}

void SceneRenderer::uploadLines(const FrameLines& lines)
{
    lineBuffer_.bind();
    lineBuffer_.allocate(lines.vertices.data(), static_cast<int>(lines.vertices.size() * sizeof(LineVertex)));
    lineBuffer_.release();
}

void SceneRenderer::setPaths(const std::vector<std::vector<Eigen::Vector3f>>& paths, const Rgba& color)
{
    pathFirsts_.clear();
    pathCounts_.clear();
    std::vector<LineVertex> vertices;
    for (const std::vector<Eigen::Vector3f>& path : paths) {
        if (path.size() < 2)
            continue;
        pathFirsts_.push_back(static_cast<GLint>(vertices.size()));
        pathCounts_.push_back(static_cast<GLsizei>(path.size()));
        for (const Eigen::Vector3f& point : path)
            vertices.push_back({{point.x(), point.y(), point.z()}, {color.r, color.g, color.b, color.a}});
    }
    pathBuffer_.bind();
    pathBuffer_.allocate(vertices.data(), static_cast<int>(vertices.size() * sizeof(LineVertex)));
    pathBuffer_.release();
}

void SceneRenderer::drawLines(GLenum mode, LineRange range)
{
    if (range.count > 0)
        glDrawArrays(mode, range.first, range.count);
}

void SceneRenderer::uploadControlPoses(const model::SceneObject& object)
{
    controlPoseMatrices_.clear();
    for (const model::Keyframe& key : object.track.keys)
        appendPoseMatrix(controlPoseMatrices_, key.pose, kControlPoseScale);
    controlPoseInstances_.bind();
    controlPoseInstances_.allocate(controlPoseMatrices_.data(), static_cast<int>(controlPoseMatrices_.size() * sizeof(float)));
    controlPoseInstances_.release();
}

void SceneRenderer::setMeshColors(const Rgba& start, const Rgba& end)
{
    meshProgram_->setUniformValue("uColor", toVector(start));
    meshProgram_->setUniformValue("uColorEnd", toVector(end));
}

void SceneRenderer::uploadJointMatrices(const model::SceneObject& object, const FrameMeshes& meshes)
{
    const std::vector<Eigen::Matrix4f> joints =
        model::jointMatrices(object.mesh->skin, object.id, *meshes.motion, meshes.scene->currentTime);
    glBindBuffer(GL_UNIFORM_BUFFER, jointMatrices_);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, static_cast<GLsizeiptr>(joints.size() * sizeof(Eigen::Matrix4f)), joints.data());
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

void SceneRenderer::drawObjects(const FrameMeshes& meshes)
{
    const model::Scene& scene = *meshes.scene;
    const Shading shading = meshes.shading;
    // X-ray: every object see-through, none hiding another, with its back faces showing.
    const float alpha = shading.xray ? kXrayAlpha : 1.0F;
    const auto setColor = [&](bool selected) {
        Rgba color = selected ? kSelectedColor : kObjectColor;
        color.a = alpha;
        setMeshColors(color, color);
    };
    if (shading.xray) {
        glEnable(GL_BLEND);
        glDepthMask(GL_FALSE);
    }
    if (shading.wireframe)
        desktopGl_->glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    // The back faces show through in X-ray and wireframe.
    cullBackFaces_ = !shading.xray && !shading.wireframe;
    const auto draw = [this](GpuMesh& mesh) { drawMesh(mesh, identityInstance_, 1); };
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const model::SceneObject& object = scene.objects[i];
        // An empty is its axes, among the lines.
        if (meshes.skeleton->isJoint(i) || !object.visible || object.empty)
            continue;
        setColor(&object == meshes.selected);
        meshProgram_->setUniformValue("uFrame", toQMatrix(poseMatrix(meshes.motion->worldPose(object.id, scene.currentTime))));
        // Skinned in the shader here only: the trail, control poses and ghost show the bind pose.
        const bool skinned = object.mesh && !object.mesh->skin.empty();
        if (skinned)
            uploadJointMatrices(object, meshes);
        meshProgram_->setUniformValue("uSkinned", skinned);
        draw(gpuMesh(object));
        meshProgram_->setUniformValue("uSkinned", false);
    }
    GpuMesh& bone = gpuMesh(boneMesh(), nullptr);
    for (const Bone& each : meshes.skeleton->bones()) {
        setColor(meshes.selected != nullptr && each.joint == meshes.selected->id);
        meshProgram_->setUniformValue("uFrame", toQMatrix(poseMatrix(each.pose, each.length)));
        draw(bone);
    }
    if (shading.wireframe)
        desktopGl_->glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    cullBackFaces_ = true;
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

void SceneRenderer::drawFrame(const Eigen::Matrix4d& viewProjectionMatrix, const Eigen::Vector3d& eyePoint,
                              const FrameLines& lines, const FrameMeshes& meshes)
{
    glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!meshProgram_->isLinked() || !lineProgram_->isLinked())
        return;
    if (meshesMayBeUnused_)
        dropUnusedMeshes();

    const model::SceneObject* selected = meshes.selected;
    const QMatrix4x4 viewProjection = toQMatrix(viewProjectionMatrix);
    const Eigen::Vector3f eye = eyePoint.cast<float>();
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);

    lineProgram_->bind();
    lineProgram_->setUniformValue("uViewProjection", viewProjection);
    lineProgram_->setUniformValue("uPointSize", kHandlePointSize);
    uploadLines(lines);
    lineArray_->bind();
    drawLines(GL_LINES, lines.grid);
    drawLines(GL_LINES, lines.axes);
    lineArray_->release();
    if (lines.drawPaths && !pathFirsts_.empty()) {
        pathArray_->bind();
        for (std::size_t i = 0; i < pathFirsts_.size(); ++i)
            glDrawArrays(GL_LINE_STRIP, pathFirsts_[i], pathCounts_[i]);
        pathArray_->release();
    }

    meshProgram_->bind();
    meshProgram_->setUniformValue("uViewProjection", viewProjection);
    meshProgram_->setUniformValue("uEye", QVector3D(eye.x(), eye.y(), eye.z()));
    meshProgram_->setUniformValue("uHighlightInstance", -1);
    meshProgram_->setUniformValue("uSkinned", false);
    glBindBufferBase(GL_UNIFORM_BUFFER, kJointMatricesBinding, jointMatrices_);
    drawObjects(meshes);

    const QMatrix4x4 selectedFrame = toQMatrix(poseMatrix(meshes.selectedParentFrame));
    // Translucent last, over everything opaque, without hiding each other. The trail too: a few
    // hundred instances opaque would hide the object, its trajectory and its control poses.
    glEnable(GL_BLEND);
    glDepthMask(GL_FALSE);
    if (!meshes.trails.empty()) {
        // Behind the objects themselves, which stand on their trails and would otherwise fight them for depth.
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0F, 1.0F);
        setMeshColors(kTrailStart, kTrailEnd);
        for (const TrailInstances& trail : meshes.trails) {
            if (trail.first + trail.count > trailInstanceCount_)
                continue; // not uploaded yet
            meshProgram_->setUniformValue("uFrame", toQMatrix(poseMatrix(trail.frame)));
            drawMesh(gpuMesh(*trail.object), trailInstances_, trail.count, trail.first);
        }
        glDisable(GL_POLYGON_OFFSET_FILL);
    }
    if (meshes.controlPoses && selected != nullptr) {
        uploadControlPoses(*selected);
        setMeshColors(kControlPoseColor, kControlPoseColor);
        meshProgram_->setUniformValue("uHighlightInstance", meshes.highlightedKey ? static_cast<int>(*meshes.highlightedKey) : -1);
        meshProgram_->setUniformValue("uHighlightColor", toVector(kSelectedKeyColor));
        meshProgram_->setUniformValue("uFrame", selectedFrame);
        drawMesh(gpuMesh(*selected), controlPoseInstances_, static_cast<int>(selected->track.keys.size()));
        meshProgram_->setUniformValue("uHighlightInstance", -1);
    }
    if (meshes.ghost && selected != nullptr) {
        setMeshColors(kGhostColor, kGhostColor);
        meshProgram_->setUniformValue("uFrame", toQMatrix(poseMatrix(*meshes.ghost)));
        drawMesh(gpuMesh(*selected), identityInstance_, 1);
    }
    glDepthMask(GL_TRUE);

    // The handles on top of everything, so that they can always be grabbed.
    glDisable(GL_DEPTH_TEST);
    lineProgram_->bind();
    lineArray_->bind();
    drawLines(GL_LINES, lines.physics);
    drawLines(GL_LINES, lines.handles);
    drawLines(GL_POINTS, lines.handlePoints);
    lineArray_->release();
    glDisable(GL_BLEND);
}

} // namespace gyre::app
