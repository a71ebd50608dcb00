#include "model/document.h"

#include "model/commands/perform_gesture_command.h"
#include "model/primitive_meshes.h"
#include "model/project_file.h"
#include "model/scene_queries.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace gyre::model {

Document::Document(QObject* parent)
    : QObject(parent)
{
    connect(&undoStack_, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

Document::~Document()
{
    // ~QUndoStack clears the stack and emits its signals, after the members declared after it are
    // gone; whoever listens would read a document half destroyed. Nothing is undone at the end.
    undoStack_.blockSignals(true);
}

const SceneObject* Document::object(ObjectId id) const { return findObject(scene_, id); }

std::shared_ptr<const SharedTrackMotion> Document::motion(ObjectId id) const
{
    const SceneObject* found = object(id);
    return found != nullptr ? motions_.motion(*found, scene_.gravity) : nullptr;
}

void Document::notifyChanged(ObjectId object, Changes changes)
{
    if (changes & (Change::Scene | Change::Gravity))
        motions_.clear();
    else if (changes & kMotionChanges)
        motions_.forget(object);
    emit changed(object, changes);
}

void Document::push(QUndoCommand* command, GestureId gesture)
{
    // Every step is a PerformGestureCommand: QUndoStack merges two steps only when they carry the
    // same gesture (id() and mergeWith), and deletes one that its gesture made obsolete.
    undoStack_.push(new PerformGestureCommand(gesture, command));
}

GestureId Document::beginGesture()
{
    openGestures_.push_back(++lastGesture_);
    return lastGesture_;
}

void Document::endGesture(GestureId gesture)
{
    const auto open = std::find(openGestures_.begin(), openGestures_.end(), gesture);
    if (open == openGestures_.end())
        return;
    openGestures_.erase(open);
    emit gestureEnded(gesture);
}

GestureId Document::newestStepGesture() const
{
    if (undoStack_.index() == 0)
        return kNoGesture;
    const auto* step = dynamic_cast<const PerformGestureCommand*>(undoStack_.command(undoStack_.index() - 1));
    return step != nullptr ? step->gesture() : kNoGesture;
}

void Document::setCurrentTime(double seconds)
{
    if (!std::isfinite(seconds))
        throw std::invalid_argument("the current time must be a finite number of seconds");
    if (seconds == scene_.currentTime)
        return;
    scene_.currentTime = seconds;
    emit currentTimeChanged(seconds);
}

void Document::startNewProject()
{
    Scene scene;
    SceneObject block;
    block.id = scene.nextObjectId++;
    block.name = primitiveName(Primitive::Block);
    block.mesh = std::make_shared<const Mesh>(primitiveMesh(Primitive::Block));
    scene.objects.push_back(std::move(block));
    replaceScene(std::move(scene), QString(), false);
}

void Document::load(const QString& path) { replaceScene(readProject(path), path, false); }

void Document::loadAsUntitled(const QString& path) { replaceScene(readProject(path), QString(), false); }

void Document::save(const QString& path)
{
    writeProject(path, scene_);
    undoStack_.setClean();
    setFilePath(path);
}

void Document::recover(const QString& recoveryPath, const QString& documentPath)
{
    replaceScene(readProject(recoveryPath), documentPath, true);
}

void Document::replaceScene(Scene scene, const QString& filePath, bool modified)
{
    // QUndoStack::clear() leaves an empty, clean stack; resetClean() then makes the clean state
    // unreachable, so a recovered document stays modified until it is saved. modifiedChanged follows cleanChanged.
    undoStack_.clear();
    if (modified)
        undoStack_.resetClean();
    const double oldTime = scene_.currentTime;
    scene_ = std::move(scene);
    setFilePath(filePath);
    notifyChanged(kNoObject, Change::Scene);
    if (scene_.currentTime != oldTime)
        emit currentTimeChanged(scene_.currentTime);
}

void Document::setFilePath(const QString& path)
{
    if (path == filePath_)
        return;
    filePath_ = path;
    emit filePathChanged(path);
}

} // namespace gyre::model
